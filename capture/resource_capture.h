#pragma once
// capture --resources: every image of the frame's graph (or the named ones) to
// resources/NAME.png + NAME.exr (resource_files.h). The inspect pass reads at most
// InspectPass::kMaxImages images a frame, so the same frame is rendered again for each batch,
// from a camera cut like the first one (no temporal history): each repeat's final image must
// equal the captured one byte for byte, or the capture fails, so every file shows the frame
// final.png shows.
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/passes/frame_result.h"

namespace ds::capture {

// What --resources asks for: all (default), none, or the listed names.
struct ResourceSelection {
    bool all = true;
    std::vector<std::string> names;  // when !all; empty = none
};
// "all", "none" or NAME,NAME,…; throws UsageError for an empty name.
ResourceSelection parse_resource_selection(const std::string& text);

// Renders the frame again (from a camera cut) with these images read back; the final image
// read back too.
using RenderInspected = std::function<FrameResult(std::span<const InspectRequest>)>;

// Reads and writes the selected images of `frame` (its ResourceSummary list) into
// `resources_dir` (made here when anything is selected) and returns report.json's
// "resources" array, in the frame's resource order. Throws UsageError for a selected name the
// frame has no image of (listing those it has), ds::Error when a repeat differs.
nlohmann::json capture_resources(const FrameResult& frame, const ResourceSelection& selection,
                                 const RenderInspected& render,
                                 const std::filesystem::path& resources_dir);

}  // namespace ds::capture
