#pragma once
// capture --reference: the reference frame (reference.h) as a capture's resource —
// resources/reference.png (the resolved, tonemapped image the scores compare), reference.exr
// (its linear HDR colour, R G B A) and reference_edges.png (its edge pixels white) — and
// report.json's "reference": the factor, its cost, and final.png scored against it.
#include <filesystem>

#include <nlohmann/json.hpp>

#include "renderer/passes/frame_result.h"
#include "renderer/renderer.h"

namespace ds::tune {

// Renders the reference of the captured view and writes the files into `resources_dir` (made
// when missing); returns report.json's "reference". Throws what render_reference throws.
nlohmann::json write_reference(Renderer& renderer, const scene::Scene& scene,
                               const scene::Camera& camera, const Settings& settings,
                               const FrameResult& frame,
                               const std::filesystem::path& resources_dir);

}  // namespace ds::tune
