#pragma once
// `depthscope diff A B` of two layer captures (capture/layer_capture.h, report.json's source
// "layer"): the same passes (name, size, depth format, samples, draw count), then draw by draw
// in order (name, kind, counts, what was not analysed), then each pass's count images pixel by
// pixel (their EXR's UINT counts: any difference). Counts are exact, so "same" means equal.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ds::capture {

struct LayerDiff {
    bool comparable = true;                // the same passes
    std::vector<std::string> differences;  // one line each
    uint32_t draws = 0, images = 0;        // compared
    uint32_t differing_draws = 0, differing_images = 0;
    bool same() const { return comparable && differences.empty(); }
    nlohmann::json to_json() const;
};

// Throws ds::Error when either folder is not a readable layer capture.
LayerDiff diff_layer_captures(const std::filesystem::path& a, const std::filesystem::path& b);

// The one-screen summary: a verdict line, then the differences (at most 40 lines).
std::string layer_diff_summary(const LayerDiff& diff, const std::string& a, const std::string& b);

}  // namespace ds::capture
