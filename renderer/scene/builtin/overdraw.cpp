// overdraw: N opaque view-filling quads at known depths, drawn back to front, so every pixel is
// shaded N times without a prepass and once with it. Depths: see scene_facts.h.
#include <cmath>
#include <string>

#include "renderer/scene/builtin/gltf_builder.h"
#include "renderer/scene/builtin/scene_facts.h"
#include "renderer/scene/builtin/scenes.h"

namespace ds::scene::builtin {

namespace {

constexpr float kOverdrawYfov = 0.8f;
constexpr float kCoverAspect = 4.0f;  // each quad covers any view up to 4:1 (plus margin)

glm::vec3 hsv_to_rgb(float h, float s, float v) {
    const glm::vec3 k = glm::mod(glm::vec3(5.0f, 3.0f, 1.0f) + h * 6.0f, 6.0f);
    return v - v * s * glm::clamp(glm::min(k, 4.0f - k), 0.0f, 1.0f);
}

constexpr Knob<int> kLayers{"overdraw_layers"};

}  // namespace

std::vector<SettingDef> overdraw_knobs() {
    return {int_knob(kLayers, "scene", 8, 1, 64,
                     "overdraw scene: number of view-filling quads, drawn back to front",
                     Invalidates::Scene)};
}

tinygltf::Model build_overdraw(const Settings& settings) {
    const int layers = knob_value(settings, kLayers);
    ModelBuilder b;
    const Geometry quad = b.add_geometry("layer_quad", make_quad({1.0f, 1.0f}));
    const float half_tan = std::tan(kOverdrawYfov * 0.5f);
    // Farthest first: the authored order is the worst case for a depth test alone.
    for (int k = layers - 1; k >= 0; --k) {
        const std::string name = "layer_" + std::to_string(k);
        MaterialSpec s;
        s.name = name;
        // Golden-ratio hue steps keep neighbouring layers distinct for any N.
        const float hue = std::fmod(static_cast<float>(k) * 0.618034f, 1.0f);
        s.base_color = glm::vec4(hsv_to_rgb(hue, 0.75f, 0.9f), 1.0f);
        s.roughness = 1.0f;
        const int mesh = b.add_mesh(name, quad, b.add_material(s));
        const float depth = facts::overdraw_layer_depth(k);
        const float side = 2.0f * depth * half_tan * kCoverAspect * 1.1f;
        b.add_node(name, mesh, {{0.0f, 0.0f, -depth}, glm::quat(1, 0, 0, 0), {side, side, 1.0f}});
    }
    CameraSpec cam;
    cam.yfov = kOverdrawYfov;
    cam.znear = 0.1f;
    cam.zfar = facts::overdraw_layer_depth(64) * 2.0f;
    b.add_camera("camera", cam, glm::vec3(0.0f), {0.0f, 0.0f, -1.0f});
    return b.finish("overdraw");
}

}  // namespace ds::scene::builtin
