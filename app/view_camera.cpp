#include "app/view_camera.h"

#include <algorithm>
#include <cmath>

#include "app/capture_source.h"

namespace ds::app {

scene::Camera look_at_camera(const LookAt& l, const scene::Scene& scene) {
    const glm::vec3 eye(l.eye[0], l.eye[1], l.eye[2]);
    const glm::vec3 target(l.target[0], l.target[1], l.target[2]);
    scene::Camera c = scene.camera;
    c.position = eye;
    c.forward = glm::normalize(target - eye);
    const glm::vec3 world_up =
        std::fabs(c.forward.y) > 0.999f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    c.up = glm::normalize(glm::cross(glm::cross(c.forward, world_up), c.forward));
    if (scene.bounds.valid()) {
        const float reach =
            glm::length(scene.bounds.center() - eye) + 0.5f * glm::length(scene.bounds.extent());
        c.zfar = std::max(c.zfar, 1.05f * reach);
    }
    return c;
}

scene::Camera view_camera(const Options& o, const scene::Scene& scene) {
    if (o.look_at) return look_at_camera(*o.look_at, scene);
    if (!o.camera_capture.empty()) return captured_camera(o.camera_capture);
    return scene.camera;
}

}  // namespace ds::app
