#pragma once
// The views lint looks from: `chosen` alone when given (--camera, --look-at), else every
// perspective camera node the scene places (Scene::cameras, "camera I (NAME)", pointer
// /nodes/N), else the "fit inside" camera (renderer/scene/fit_inside.h).
#include <optional>
#include <vector>

#include "capture/lint/lint.h"

namespace ds::lint {

std::vector<View> scene_views(const scene::Scene& scene, const std::optional<View>& chosen);

}  // namespace ds::lint
