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
    // shaded, discarded, rasterized, and where the capture has them (settings zfight,
    // equal_check) zfight (competitors) and equal_check (marks: 1 hole, 2 tie); width * height
    // values each (empty: absent), row 0 = top.
    std::array<std::vector<uint32_t>, 5> counts;
    std::array<uint32_t, 5> max{};
};

struct LayerCaptureData {
    std::filesystem::path dir;
    nlohmann::json report;
    std::vector<LayerPassImages> images;
};

inline constexpr std::array<const char*, 3> kLayerCountKinds = {"shaded", "discarded",
                                                                "rasterized"};
// Every per-pixel image a pass may have: the counts, then the depth checks' (optional).
inline constexpr std::array<const char*, 5> kLayerImageKinds = {"shaded", "discarded", "rasterized",
                                                                "zfight", "equal_check"};

// Throws ds::Error when `dir` is not a readable layer capture.
LayerCaptureData load_layer_capture(const std::filesystem::path& dir);

// A JSON file, or ds::Error "FILE: why" (unreadable, malformed).
nlohmann::json read_json_file(const std::filesystem::path& file);
// `dir`/report.json of a layer capture ("source": "layer"), or ds::Error.
nlohmann::json read_layer_report(const std::filesystem::path& dir);
bool is_layer_capture(const std::filesystem::path& dir);

// Counts as the count heat map (view::count_color, black 0 .. white `max`), RGBA8.
std::vector<uint8_t> count_heat_rgba(const std::vector<uint32_t>& counts, uint32_t max);
// EQUAL check marks as colours: 0 transparent black, 1 (hole) magenta, 2 (tie) yellow.
std::vector<uint8_t> marks_rgba(const std::vector<uint32_t>& marks);

}  // namespace ds::capture
