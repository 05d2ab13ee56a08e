#include "ui/camera_controller.h"

#include <algorithm>
#include <cmath>

namespace ds::ui {
namespace {

constexpr float kOrbitRadiansPerPixel = 0.005f;
constexpr float kLookRadiansPerPixel = 0.003f;
constexpr float kDollyPerNotch = 0.15f;  // fraction of the distance
constexpr float kMaxPitch = 1.55f;       // just short of straight up or down

// Rotates `forward` by yaw around +Y and pitch around the camera's right axis, keeping it
// away from the poles.
glm::vec3 rotate(glm::vec3 forward, float yaw, float pitch) {
    const float current = std::asin(std::clamp(forward.y, -1.0f, 1.0f));
    const float new_pitch = std::clamp(current + pitch, -kMaxPitch, kMaxPitch);
    float heading = std::atan2(forward.x, -forward.z) + yaw;
    return glm::normalize(glm::vec3(std::cos(new_pitch) * std::sin(heading), std::sin(new_pitch),
                                    -std::cos(new_pitch) * std::cos(heading)));
}

glm::vec3 up_for(const glm::vec3& forward) {
    // Looking straight up or down (a top-down glTF camera): +Y cannot give a right axis.
    const glm::vec3 reference =
        std::abs(forward.y) > 0.999f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
    const glm::vec3 right = glm::normalize(glm::cross(forward, reference));
    return glm::normalize(glm::cross(right, forward));
}

}  // namespace

bool CameraInput::any() const {
    return orbit != glm::vec2(0.0f) || pan != glm::vec2(0.0f) || dolly != 0.0f ||
           look != glm::vec2(0.0f) || move != glm::vec3(0.0f) || frame;
}

void CameraController::reset(const scene::Camera& camera, const scene::Bounds& content) {
    camera_ = camera;
    bounds_ = content;
    scene_size_ = content.valid() ? std::max(glm::length(content.extent()), 1e-3f) : 1.0f;
    // Orbit around the point the camera looks at, at the content's centre's distance.
    const glm::vec3 centre = content.valid() ? content.center() : camera.position + camera.forward;
    distance_ = std::max(glm::dot(centre - camera.position, camera.forward), 1e-3f);
    target_ = camera.position + camera.forward * distance_;
}

void CameraController::frame_scene() {
    const scene::Camera framed = scene::frame_bounds(bounds_, camera_.yfov);
    camera_.position = framed.position;
    camera_.forward = framed.forward;
    camera_.up = framed.up;
    distance_ = glm::length(bounds_.center() - framed.position);
    target_ = bounds_.center();
}

bool CameraController::update(const CameraInput& in) {
    if (!in.any()) return false;
    if (in.frame && bounds_.valid()) frame_scene();
    glm::vec3 forward = camera_.forward;
    if (in.orbit != glm::vec2(0.0f)) {  // around target_, at distance_
        forward = rotate(forward, in.orbit.x * kOrbitRadiansPerPixel,
                         -in.orbit.y * kOrbitRadiansPerPixel);
        camera_.position = target_ - forward * distance_;
    }
    if (in.look != glm::vec2(0.0f)) {  // fly: turn in place, the target follows
        forward =
            rotate(forward, in.look.x * kLookRadiansPerPixel, -in.look.y * kLookRadiansPerPixel);
        target_ = camera_.position + forward * distance_;
    }
    camera_.forward = forward;
    camera_.up = up_for(forward);
    const glm::vec3 right = glm::normalize(glm::cross(forward, camera_.up));
    if (in.pan != glm::vec2(0.0f)) {  // the point under the cursor stays under it
        const float per_pixel =
            2.0f * distance_ * std::tan(0.5f * camera_.yfov) / std::max(in.viewport_height, 1.0f);
        const glm::vec3 shift = (-in.pan.x * right + in.pan.y * camera_.up) * per_pixel;
        camera_.position += shift;
        target_ += shift;
    }
    if (in.dolly != 0.0f) {
        const float factor = std::pow(1.0f - kDollyPerNotch, in.dolly);
        distance_ = std::max(distance_ * factor, scene_size_ * 1e-3f);
        camera_.position = target_ - forward * distance_;
    }
    if (in.move != glm::vec3(0.0f)) {
        const float speed = scene_size_ * 0.25f * (in.fast ? 4.0f : 1.0f);
        const glm::vec3 step =
            (in.move.x * right + in.move.y * glm::vec3(0, 1, 0) + in.move.z * forward) * speed *
            in.dt;
        camera_.position += step;
        target_ += step;
    }
    return true;
}

}  // namespace ds::ui
