#pragma once
// A capture folder from what the Vulkan layer wrote for the chosen frame (layer/capture_output.h):
// report.json ("source": "layer": the device, the application, the frame, its passes and draws
// with their counts, the pipelines with their early-Z verdicts, not_analysed, the cost) and,
// for every pass with a depth attachment, resources/PASS_shaded, _discarded and _rasterized as
// PNG (the count heat map, 0..the pass's largest count) and EXR (the raw counts, UINT).
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ds::capture {

// Reads `layer_dir`/capture.json and its files; writes into `out_dir` (a staging folder).
// `command`: the application's command line, for the report. Throws ds::Error.
nlohmann::json write_layer_capture(const std::filesystem::path& layer_dir,
                                   const std::filesystem::path& out_dir,
                                   const std::vector<std::string>& command);

// One per-pixel image of a layer capture: `dir`/STEM.png (the count heat map over 0..max, or
// with `marks` the EQUAL check's palette: 0 none, 1 hole, 2 tie) and STEM.exr (exact, UINT).
nlohmann::json write_layer_image(const std::filesystem::path& dir, const std::string& stem,
                                 uint32_t width, uint32_t height,
                                 const std::vector<uint32_t>& values, bool marks = false);

// A draw's name: its innermost debug-utils label, else "PASS draw N (PIPELINE)" (the pass's
// name, the draw's index in it, and its pipeline's debug-utils name or "pipeline K", K its order
// of first use in the frame).
std::string layer_draw_name(const nlohmann::json& draw, const std::string& pass_name,
                            const std::string& pipeline);

}  // namespace ds::capture
