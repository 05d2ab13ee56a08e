#include "renderer/scene/scene.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace ds::scene {

const char* to_string(AlphaMode mode) {
    switch (mode) {
        case AlphaMode::Opaque:
            return "opaque";
        case AlphaMode::Mask:
            return "mask";
        case AlphaMode::Blend:
            return "blend";
    }
    return "unknown";
}

const char* to_string(SceneCamera::Type type) {
    return type == SceneCamera::Type::Orthographic ? "orthographic" : "perspective";
}

glm::mat4 Camera::view() const {
    return glm::lookAt(position, position + forward, up);
}

uint64_t Scene::triangle_count() const {
    uint64_t triangles = 0;
    for (const Instance& instance : instances)
        if (instance.mesh < meshes.size()) triangles += meshes[instance.mesh].indices.size() / 3;
    return triangles;
}

const Material& Scene::instance_material(uint32_t instance) const {
    return materials.at(meshes.at(instances.at(instance).mesh).material);
}

SurfaceName Scene::instance_name(uint32_t instance) const {
    const Instance& i = instances.at(instance);
    return {meshes.at(i.mesh).name, instance_material(instance).name, i.node};
}

Camera frame_bounds(const Bounds& bounds, float yfov) {
    Camera camera;
    camera.yfov = yfov;
    if (!bounds.valid()) return camera;
    // From the front-right, a little above: the classic 3/4 view shows three faces of a box.
    constexpr float kAzimuth = 0.6f;    // radians around +Y, from +Z towards +X
    constexpr float kElevation = 0.4f;  // radians above the horizon
    const glm::vec3 to_eye{std::cos(kElevation) * std::sin(kAzimuth), std::sin(kElevation),
                           std::cos(kElevation) * std::cos(kAzimuth)};
    float radius = 0.5f * glm::length(bounds.extent());
    if (!(radius > 1e-6f) || !std::isfinite(radius)) radius = 1.0f;
    // The sphere fits the vertical field of view with a 10% margin.
    const float distance = 1.1f * radius / std::sin(0.5f * yfov);
    camera.position = bounds.center() + to_eye * distance;
    camera.forward = -to_eye;
    camera.up =
        glm::normalize(glm::cross(glm::cross(camera.forward, glm::vec3(0, 1, 0)), camera.forward));
    // Near/far scale with the scene, leaving room to orbit and zoom out; reverse-Z keeps the
    // precision good at this ratio.
    camera.znear = std::max(radius * 1e-3f, 1e-4f);
    camera.zfar = distance + 4.0f * radius;
    return camera;
}

// KHR_texture_transform's matrix, translation * rotation * scale, with the rotation the
// extension's example pins down (offset [0, 1], rotation pi/2, scale 0.5 shows the lower-left
// quadrant turned clockwise): u' = cos*u + sin*v, v' = -sin*u + cos*v.
std::array<glm::vec3, 2> TextureRef::uv_rows() const {
    const float c = std::cos(rotation), s = std::sin(rotation);
    return {glm::vec3(c * scale.x, s * scale.y, offset.x),
            glm::vec3(-s * scale.x, c * scale.y, offset.y)};
}

}  // namespace ds::scene
