#pragma once
// `depthscope pixel`'s output: the pixel history of one frame (its PixelHistory) as
// JSON and as a table. Names come from the scene (Scene::instance_name), linear depths from
// the frame's depth planes (view::linear_depth).
#include <string>

#include <nlohmann/json.hpp>

#include "renderer/passes/frame_result.h"
#include "renderer/passes/pixel_history.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings.h"

namespace ds::capture {

struct PixelReportInput {
    const scene::Scene& scene;
    const Settings& settings;
    const FrameResult& frame;  // rendered with a PixelQuery, read back
};

// {"pixel": [x, y], "fragments": [...]} in submission order, with the frame's context (scene,
// size, settings, depth, the final colour of the pixel, dropped records).
nlohmann::json pixel_history_json(const PixelReportInput& in);
// One line per fragment under a header line; "no fragment covered ..." when none did.
std::string pixel_history_table(const PixelReportInput& in);

}  // namespace ds::capture
