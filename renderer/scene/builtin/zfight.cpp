// zfight: exactly coplanar and nearly coplanar quad pairs at distances from 1 m to 5 km under a
// camera with a long near/far range, to compare depth formats and reverse-Z. Layout and
// offsets: see scene_facts.h.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "renderer/scene/builtin/gltf_builder.h"
#include "renderer/scene/builtin/scene_facts.h"
#include "renderer/scene/builtin/scenes.h"

namespace ds::scene::builtin {

namespace {

constexpr float kZfightYfov = 0.8f;
constexpr float kAspect = 16.0f / 9.0f;
// Tilted away from the view so depth varies across each quad: coplanar triangles with
// different diagonals then tie only up to rounding, which is what z-fighting is.
constexpr float kTilt = 0.7f;

float lerp_log(float a, float b, float t) {
    return a * std::pow(b / a, t);
}

struct Slot {
    glm::vec3 centre;  // of the slot, in camera (= world) space
    float size;        // side of each square
};

Slot slot_at(int i, int count, float distance) {
    const int cols = std::max(1, static_cast<int>(std::ceil(std::sqrt(count * kAspect))));
    const int rows = (count + cols - 1) / cols;
    const float ndc_x = -1.0f + (2.0f * static_cast<float>(i % cols) + 1.0f) / cols;
    const float ndc_y = 1.0f - (2.0f * static_cast<float>(i / cols) + 1.0f) / rows;
    const float half_tan = std::tan(kZfightYfov * 0.5f);
    const float cell_w = 2.0f / cols * distance * half_tan * kAspect;
    const float cell_h = 2.0f / rows * distance * half_tan;
    return {{ndc_x * distance * half_tan * kAspect, ndc_y * distance * half_tan, -distance},
            0.4f * std::min(cell_w * 0.5f, cell_h)};
}

constexpr Knob<int> kPairs{"zfight_pairs"};

}  // namespace

std::vector<SettingDef> zfight_knobs() {
    return {int_knob(kPairs, "scene", 6, 1, 16,
                     "zfight scene: number of coplanar / nearly coplanar quad pairs",
                     Invalidates::Scene)};
}

tinygltf::Model build_zfight(const Settings& settings) {
    const int pairs = knob_value(settings, kPairs);
    ModelBuilder b;
    const Geometry quad = b.add_geometry("square", make_quad({1.0f, 1.0f}));
    // A and B: the exactly coplanar pair; front and back: the nearly coplanar pair.
    const std::array<const char*, 4> names = {"coplanar_a", "coplanar_b", "near_front",
                                              "near_back"};
    const std::array<glm::vec3, 4> colours = {glm::vec3(0.9f, 0.1f, 0.1f),
                                              {0.1f, 0.85f, 0.9f},
                                              {0.95f, 0.85f, 0.1f},
                                              {0.2f, 0.2f, 0.95f}};
    std::array<int, 4> meshes{};
    for (size_t m = 0; m < 4; ++m) {
        MaterialSpec s;
        s.name = names[m];
        s.base_color = glm::vec4(colours[m], 1.0f);
        s.roughness = 1.0f;
        s.double_sided = true;
        meshes[m] = b.add_mesh(names[m], quad, b.add_material(s));
    }
    const glm::quat tilt = yaw(kTilt);
    const glm::vec3 along = tilt * glm::vec3(1.0f, 0.0f, 0.0f);
    // Rolling B by 90 degrees in its plane flips its diagonal relative to A.
    const glm::quat roll =
        tilt * glm::angleAxis(std::numbers::pi_v<float> * 0.5f, glm::vec3(0.0f, 0.0f, 1.0f));
    for (int i = 0; i < pairs; ++i) {
        const float t = pairs > 1 ? static_cast<float>(i) / static_cast<float>(pairs - 1) : 0.0f;
        const float d = lerp_log(facts::kZfightNearest, facts::kZfightFarthest, t);
        const Slot slot = slot_at(i, pairs, d);
        const glm::vec3 left = slot.centre - along * (slot.size * 0.6f);
        const glm::vec3 right = slot.centre + along * (slot.size * 0.6f);
        const glm::vec3 scale(slot.size, slot.size, 1.0f);
        const std::string tag = "_" + std::to_string(i);
        b.add_node(names[0] + tag, meshes[0], {left, tilt, scale});
        b.add_node(names[1] + tag, meshes[1], {left, roll, scale});
        b.add_node(names[2] + tag, meshes[2], {right, tilt, scale});
        // Pushed back along the view ray (the camera is at the origin) by the facts' view-depth
        // gap, parallel to the front one; slightly smaller so parallax never shows its edges:
        // it is seen only where the depth test gets the order wrong.
        const float depth = -right.z;
        const glm::vec3 back = right * (1.0f + facts::zfight_gap_metres(depth) / depth);
        b.add_node(names[3] + tag, meshes[3], {back, tilt, scale * glm::vec3(0.8f, 0.8f, 1.0f)});
    }
    CameraSpec cam;
    cam.yfov = kZfightYfov;
    cam.aspect = kAspect;
    cam.znear = facts::kZfightZnear;
    cam.zfar = facts::kZfightZfar;
    b.add_camera("camera", cam, glm::vec3(0.0f), {0.0f, 0.0f, -1.0f});
    return b.finish("zfight");
}

}  // namespace ds::scene::builtin
