// edges: thin, high-frequency geometry for MSAA work. Sub-pixel rods and wires, a fine grating
// and thin slanted slabs, dark against a bright backdrop and ground, at many angles, so every
// edge orientation and sub-pixel coverage case appears.
#include <numbers>
#include <string>

#include "renderer/scene/builtin/angles.h"
#include "renderer/scene/builtin/gltf_builder.h"
#include "renderer/scene/builtin/scenes.h"

namespace ds::scene::builtin {

namespace {

const glm::vec3 kAxisX(1.0f, 0.0f, 0.0f);
const glm::vec3 kAxisZ(0.0f, 0.0f, 1.0f);

int plain_material(ModelBuilder& b, const char* name, glm::vec3 colour, glm::vec3 emissive,
                   float metallic = 0.0f) {
    MaterialSpec s;
    s.name = name;
    s.base_color = glm::vec4(colour, 1.0f);
    s.emissive = emissive;
    s.metallic = metallic;
    s.roughness = 0.5f;
    return b.add_material(s);
}

void add_backdrop(ModelBuilder& b) {
    // Emissive so the background stays bright whatever the sun does.
    const int bright = plain_material(b, "bright_backdrop", {0.95f, 0.95f, 0.92f}, glm::vec3(0.8f));
    const int ground = plain_material(b, "bright_ground", {0.85f, 0.85f, 0.85f}, glm::vec3(0.5f));
    b.add_node("backdrop", b.add_mesh("backdrop", make_quad({30.0f, 16.0f}), bright),
               {{0.0f, 8.0f, -8.0f}});
    b.add_node("ground", b.add_mesh("ground", make_quad({30.0f, 30.0f}), ground),
               {{0.0f, 0.0f, -4.0f}, glm::angleAxis(-kPi * 0.5f, kAxisX)});
}

void add_fans(ModelBuilder& b, int dark) {
    // One rod mesh: 2.5 m long, 2 cm thick, pointing up from its origin. Wires are the same
    // mesh scaled to 4 mm: same draw group, sub-pixel width at the default view.
    const int rod = b.add_mesh("rod", make_box({-0.01f, 0.0f, -0.01f}, {0.01f, 2.5f, 0.01f}), dark);
    const int spokes = 24;
    for (int i = 0; i < spokes; ++i) {
        const float a = kPi * (static_cast<float>(i) / static_cast<float>(spokes - 1) - 0.5f);
        const glm::quat roll = glm::angleAxis(a, kAxisZ);
        b.add_node("rod_" + std::to_string(i), rod, {{-3.2f, 0.3f, -4.0f}, roll});
        b.add_node("wire_" + std::to_string(i), rod,
                   {{3.2f, 0.3f, -4.0f}, roll, {0.2f, 1.0f, 0.2f}});
    }
}

void add_grating(ModelBuilder& b, int dark) {
    // 48 slats, 1.5 cm wide, every 4 cm: about one to two pixels per period at 720p.
    const int slat =
        b.add_mesh("slat", make_box({-0.0075f, 0.0f, -0.02f}, {0.0075f, 1.6f, 0.02f}), dark);
    for (int i = 0; i < 48; ++i) {
        const float x = -0.96f + 0.04f * static_cast<float>(i);
        b.add_node("slat_" + std::to_string(i), slat, {{x, 0.2f, -3.5f}});
    }
    // A second grating turned 60 degrees in its plane, behind the first (moire).
    for (int i = 0; i < 48; ++i) {
        const glm::quat roll = glm::angleAxis(kPi / 3.0f, kAxisZ);
        const glm::vec3 at = glm::vec3(0.0f, 1.0f, -5.0f) +
                             roll * glm::vec3(-0.96f + 0.04f * static_cast<float>(i), -0.8f, 0);
        b.add_node("slat_turned_" + std::to_string(i), slat, {at, roll});
    }
}

void add_slabs(ModelBuilder& b) {
    const int grey = plain_material(b, "slab_metal", {0.25f, 0.27f, 0.3f}, glm::vec3(0.0f), 0.8f);
    const int slab =
        b.add_mesh("slab", make_box({-0.6f, -0.3f, -0.005f}, {0.6f, 0.3f, 0.005f}), grey);
    for (int i = 0; i < 9; ++i) {
        const float t = static_cast<float>(i) / 8.0f;
        const glm::quat turn = glm::angleAxis(kPi * (0.05f + 0.45f * t), glm::vec3(0, 1, 0)) *
                               glm::angleAxis(kPi * 0.11f * static_cast<float>(i), kAxisZ);
        b.add_node("slab_" + std::to_string(i), slab,
                   {{-2.4f + 0.6f * static_cast<float>(i), 2.4f + 0.15f * (i % 3), -3.0f}, turn});
    }
}

}  // namespace

tinygltf::Model build_edges(const Settings& /*settings*/) {
    ModelBuilder b;
    add_backdrop(b);
    const int dark = plain_material(b, "dark_rod", {0.05f, 0.05f, 0.06f}, glm::vec3(0.0f));
    add_fans(b, dark);
    add_grating(b, dark);
    add_slabs(b);
    CameraSpec cam;
    cam.yfov = 0.9f;
    cam.znear = 0.1f;
    cam.zfar = 100.0f;
    b.add_camera("camera", cam, {0.0f, 1.7f, 2.5f}, {0.0f, 1.6f, -4.0f});
    return b.finish("edges");
}

}  // namespace ds::scene::builtin
