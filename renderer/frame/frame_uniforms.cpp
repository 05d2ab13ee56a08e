#include "renderer/frame/frame_uniforms.h"

#include "renderer/settings/frame_knobs.h"

#include <cmath>

#include "renderer/passes/shadow.h"

namespace ds {
namespace {

// Sky and ground colours of the hemispherical ambient (scaled by `ambient`).
constexpr glm::vec3 kSkyAmbient{0.55f, 0.70f, 1.00f};
constexpr glm::vec3 kGroundAmbient{0.35f, 0.30f, 0.25f};

// Towards the sun: azimuth 0 towards +Z, 90 towards +X; elevation above the horizon.
glm::vec3 to_sun(const Settings& settings) {
    const float az = glm::radians(knob_value(settings, knobs::kSunAzimuth));
    const float el = glm::radians(knob_value(settings, knobs::kSunElevation));
    return {std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
}

}  // namespace

glm::mat4 perspective(float yfov, float aspect, float znear, float zfar, bool reverse_z) {
    const float f = 1.0f / std::tan(yfov * 0.5f);
    glm::mat4 p(0.0f);
    p[0][0] = f / aspect;
    p[1][1] = -f;
    p[2][3] = -1.0f;
    if (reverse_z) {
        p[2][2] = znear / (zfar - znear);
        p[3][2] = znear * zfar / (zfar - znear);
    } else {
        p[2][2] = zfar / (znear - zfar);
        p[3][2] = znear * zfar / (znear - zfar);
    }
    return p;
}

passes::FrameUniforms frame_uniforms(const UniformInputs& in) {
    const scene::Camera& cam = in.camera;
    const float aspect = float(in.size.width) / float(in.size.height);
    passes::FrameUniforms u;
    u.view = cam.view();
    const std::optional<float> fov = knob_value(in.settings, knobs::kFov);  // none: the scene's
    const float yfov = fov ? glm::radians(*fov) : cam.yfov;
    u.projection = perspective(yfov, aspect, cam.znear, cam.zfar, in.options.reverse_z);
    u.view_projection = u.projection * u.view;
    u.inverse_view_projection = glm::inverse(u.view_projection);
    u.inverse_projection = glm::inverse(u.projection);
    u.previous_view_projection =
        in.previous_view_projection ? *in.previous_view_projection : u.view_projection;
    const glm::vec3 l = to_sun(in.settings);
    u.sun_view_projection = passes::ShadowPass::fit_sun(in.scene_bounds, l);
    u.camera_position = glm::vec4(cam.position, 1.0f);
    u.sun_direction = glm::vec4(l, 0.0f);
    u.sun_radiance = glm::vec4(in.sun.color * knob_value(in.settings, knobs::kSunIntensity), 0.0f);
    const float ambient = knob_value(in.settings, knobs::kAmbient);
    u.sky_ambient = glm::vec4(kSkyAmbient * ambient, 0.0f);
    u.ground_ambient = glm::vec4(kGroundAmbient * ambient, 0.0f);
    u.viewport = {float(in.size.width), float(in.size.height), 1.0f / float(in.size.width),
                  1.0f / float(in.size.height)};
    u.depth_params = {cam.znear, cam.zfar, in.options.reverse_z ? 1.0f : 0.0f,
                      knob_value(in.settings, knobs::kExposure)};
    u.alpha = glm::vec4(in.options.alpha_cutoff.value_or(-1.0f),
                        in.options.alpha_level0 ? 1.0f : 0.0f, 0.0f, 0.0f);
    u.flags = glm::uvec4(in.flags | (in.options.reverse_z ? passes::kFrameReverseZ : 0u),
                         uint32_t(in.frame_number), 0u, 0u);
    return u;
}

}  // namespace ds
