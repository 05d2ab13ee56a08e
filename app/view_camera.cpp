#include "app/view_camera.h"

#include <algorithm>
#include <cmath>

#include "app/capture_source.h"
#include "renderer/common/error.h"
#include "renderer/common/quoted.h"

namespace ds::app {
namespace {

using scene::SceneCamera;

bool usable(const SceneCamera& c) {
    return c.type == SceneCamera::Type::Perspective && c.camera;
}

// "2 'top'" or "2 (unnamed)"
std::string label(const scene::Scene& scene, size_t index) {
    const std::string& name = scene.cameras[index].name;
    return std::to_string(index) + " " + (name.empty() ? "(unnamed)" : quote(name));
}

// "(its cameras: 0 'camera', 1 'side')", or why there is none to pick.
std::string choices(const scene::Scene& scene) {
    std::string list;
    for (size_t i = 0; i < scene.cameras.size(); ++i)
        if (usable(scene.cameras[i])) list += (list.empty() ? "" : ", ") + label(scene, i);
    if (!list.empty()) return "(its cameras: " + list + ")";
    if (scene.cameras.empty()) return "(it has no camera nodes)";
    return "(none of its camera nodes is perspective: the renderer is perspective only)";
}

// The index SPEC names, or throws the unknown camera's error.
size_t find_camera(const std::string& spec, const scene::Scene& scene) {
    const std::string what = "--camera " + quote(spec) + ": " + escaped(scene.name);
    if (const std::optional<uint32_t> index = parse_digits(spec)) {
        if (*index < scene.cameras.size()) return *index;
        throw UsageError(what + " has no camera node " + spec + " " + choices(scene));
    }
    const auto it = std::find_if(scene.cameras.begin(), scene.cameras.end(),
                                 [&](const SceneCamera& c) { return c.name == spec; });
    if (it == scene.cameras.end())
        throw UsageError(what + " has no camera node of that name " + choices(scene));
    return size_t(it - scene.cameras.begin());
}

}  // namespace

scene::Camera look_at_camera(const LookAt& l, const scene::Scene& scene) {
    const glm::vec3 eye(l.eye[0], l.eye[1], l.eye[2]);
    const glm::vec3 target(l.target[0], l.target[1], l.target[2]);
    scene::Camera c = scene.camera;
    c.position = eye;
    c.forward = glm::normalize(target - eye);
    c.up = glm::normalize(glm::cross(glm::cross(c.forward, glm::vec3(0, 1, 0)), c.forward));
    if (l.fov) c.yfov = glm::radians(*l.fov);
    if (scene.bounds.valid()) {
        const float reach =
            glm::length(scene.bounds.center() - eye) + 0.5f * glm::length(scene.bounds.extent());
        c.zfar = std::max(c.zfar, 1.05f * reach);
    }
    return c;
}

scene::Camera node_camera(const std::string& spec, const scene::Scene& scene) {
    const size_t index = find_camera(spec, scene);
    const SceneCamera& c = scene.cameras[index];
    const std::string what = "--camera " + quote(spec) + ": camera " + label(scene, index) +
                             " of " + escaped(scene.name);
    if (c.type == SceneCamera::Type::Orthographic)
        throw UsageError(what +
                         " is orthographic: not supported (the renderer is perspective only)");
    if (!c.camera)
        throw UsageError(what + " has no view direction (its node's transform collapses it)");
    return *c.camera;
}

std::optional<scene::Camera> chosen_camera(const Options& o, const scene::Scene& scene) {
    if (o.look_at) return look_at_camera(*o.look_at, scene);
    if (!o.camera.empty()) return node_camera(o.camera, scene);
    return std::nullopt;
}

scene::Camera view_camera(const Options& o, const scene::Scene& scene) {
    if (std::optional<scene::Camera> chosen = chosen_camera(o, scene)) return *chosen;
    if (!o.camera_of.empty()) return captured_camera(o.camera_of);
    return scene.camera;
}

}  // namespace ds::app
