#pragma once
// A layer capture folder (capture/layer_capture.h) read back for display: its report and, per
// pass with a depth attachment, the three count images from their EXR files (exact counts).
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ds::capture {

struct LayerPassImages {
    uint32_t pass = 0;  // index into report["passes"]
    std::string name;
    uint32_t width = 0, height = 0;
    // shaded, discarded, rasterized: width * height counts, row 0 = top.
    std::array<std::vector<uint32_t>, 3> counts;
    std::array<uint32_t, 3> max{};
};

struct LayerCaptureData {
    std::filesystem::path dir;
    nlohmann::json report;
    std::vector<LayerPassImages> images;
};

inline constexpr std::array<const char*, 3> kLayerCountKinds = {"shaded", "discarded",
                                                                "rasterized"};

// Throws ds::Error when `dir` is not a readable layer capture.
LayerCaptureData load_layer_capture(const std::filesystem::path& dir);

}  // namespace ds::capture
