// The views lint looks from (lint.h): the chosen camera, else every perspective camera node
// of the scene, else "fit inside" (renderer/scene/fit_inside.h, the inspector's view for
// interiors: a scene without cameras is most often seen from within).
#include "capture/lint/lint_views.h"

#include "renderer/scene/fit_inside.h"

namespace ds::lint {

std::vector<View> scene_views(const scene::Scene& scene, const std::optional<View>& chosen) {
    if (chosen) return {*chosen};
    std::vector<View> out;
    for (size_t i = 0; i < scene.cameras.size(); ++i) {
        const scene::SceneCamera& c = scene.cameras[i];
        if (!c.camera) continue;
        out.push_back({"camera " + std::to_string(i) + (c.name.empty() ? "" : " (" + c.name + ")"),
                       c.gltf_node >= 0 ? "/nodes/" + std::to_string(c.gltf_node) : "", *c.camera});
    }
    if (out.empty()) out.push_back({"fit inside", "", scene::fit_inside(scene, scene.camera)});
    return out;
}

}  // namespace ds::lint
