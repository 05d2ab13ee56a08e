// The atrium's dressing: curtains (double-sided cloth), planters with alpha-masked foliage,
// coplanar decals (BLEND) and the default camera.
#include <array>
#include <numbers>
#include <string>

#include "renderer/scene/builtin/angles.h"
#include "renderer/scene/builtin/atrium_layout.h"

namespace ds::scene::builtin::atrium {

namespace {

float bay_centre_z(int k) {
    return -kHalfLength + kBay * (static_cast<float>(k) + 0.5f);
}

void add_curtains(ModelBuilder& b) {
    const int fabric = b.add_texture("atrium_fabric", fabric_texture(64, 6));
    const std::array<glm::vec4, 3> colours = {glm::vec4(0.62f, 0.08f, 0.07f, 1.0f),
                                              glm::vec4(0.12f, 0.4f, 0.16f, 1.0f),
                                              glm::vec4(0.12f, 0.2f, 0.55f, 1.0f)};
    const std::array<const char*, 3> names = {"curtain_red", "curtain_green", "curtain_blue"};
    // One set of vertices, three meshes: glTF lets primitives share accessors.
    const Geometry cloth = b.add_geometry("curtain", make_curtain(3.0f, 4.6f, 4, 0.09f));
    std::array<int, 3> meshes{}, materials{};
    for (size_t c = 0; c < 3; ++c) {
        MaterialSpec s;
        s.name = names[c];
        s.base_color = colours[c];
        s.base_color_texture = fabric;
        s.roughness = 0.95f;
        s.double_sided = true;  // seen from the courtyard and from the gallery
        materials[c] = b.add_material(s);
        meshes[c] = b.add_mesh(names[c], cloth, materials[c]);
    }
    // Hung in front of every other upper bay, just on the courtyard side of the arcades.
    const float x = kArcadeX - 0.65f, top = kUpperSpringing - 0.2f;
    int n = 0;
    for (int k = 1; k < kBays; k += 2) {
        for (float side : {-1.0f, 1.0f}) {
            const int mesh = meshes[static_cast<size_t>(n++ % 3)];
            b.add_node(
                std::string("curtain_") + std::to_string(k) + (side < 0 ? "_left" : "_right"), mesh,
                {{side * x, top, bay_centre_z(k)}, yaw(-side * kHalfPi)});
        }
    }
    // Festival banners strung across the courtyard between the upper arcades: seen down the
    // axis they hang one behind the other.
    const Geometry strip = b.add_geometry("banner", make_curtain(2.0f * x, 1.2f, 5, 0.06f));
    std::array<int, 3> banners{};
    for (size_t c = 0; c < 3; ++c) {
        banners[c] = b.add_mesh(std::string("banner_") + (names[c] + 8), strip, materials[c]);
    }
    for (int k = 0; k < kBays - 1; ++k) {
        const float z = -kHalfLength + kBay * static_cast<float>(k + 1);
        b.add_node("banner_" + std::to_string(k), banners[static_cast<size_t>(k % 3)],
                   {{0.0f, top + 0.3f, z}});
    }
}

void add_planters(ModelBuilder& b, const Materials& m) {
    MaterialSpec leaves;
    leaves.name = "foliage";
    leaves.base_color_texture = b.add_texture("atrium_leaves", leaf_texture(128, 7));
    leaves.roughness = 0.7f;
    leaves.alpha = Alpha::Mask;
    leaves.alpha_cutoff = 0.5f;
    leaves.double_sided = true;
    const int foliage = b.add_material(leaves);
    const int planter = b.add_mesh("planter", make_frustum(0.5f, 0.65f, 0.7f, 20), m.terracotta);
    const int plant = b.add_mesh("plant", make_plant_cards(0.9f, 1.9f, 4, 6), foliage);
    // A central row and two side rows, authored far to near.
    const std::array<glm::vec2, 13> spots = {
        glm::vec2(0, -14), {-3, -11}, {3, -11}, {0, -8}, {-3, -5}, {3, -5}, {0, -2},
        {-3, 1},           {3, 1},    {0, 4},   {-3, 7}, {3, 7},   {0, 10}};
    for (size_t i = 0; i < spots.size(); ++i) {
        const glm::vec3 at(spots[i].x, 0.0f, spots[i].y);
        const std::string tag = std::to_string(i);
        b.add_node("planter_" + tag, planter, {at});
        const float turn = 0.7f * static_cast<float>(i);
        const float size = 0.85f + 0.3f * hash01(static_cast<uint32_t>(i), 0, 11);
        b.add_node("plant_" + tag, plant,
                   {at + glm::vec3(0, 0.55f, 0), yaw(turn), glm::vec3(size)});
    }
}

struct Decal {
    const char* name;
    Surface surface;
    GridRange cells;
    int material;
};

// Decals are whole cells of the wall / floor grid: the same vertices, the same triangles,
// an identity node transform. They are exactly coplanar, as Sponza's overlays are.
void add_decals(ModelBuilder& b) {
    auto decal_material = [&](const char* name, int texture) {
        MaterialSpec s;
        s.name = name;
        s.base_color_texture = texture;
        s.roughness = 0.8f;
        s.alpha = Alpha::Blend;
        return b.add_material(s);
    };
    const int red = decal_material(
        "decal_poster_red",
        b.add_texture("atrium_poster_red", poster_texture(128, {0.7f, 0.12f, 0.1f}, 8),
                      SamplerKind::Clamp));
    const int blue = decal_material(
        "decal_poster_blue",
        b.add_texture("atrium_poster_blue", poster_texture(128, {0.15f, 0.3f, 0.7f}, 9),
                      SamplerKind::Clamp));
    const int stain = decal_material(
        "decal_stain", b.add_texture("atrium_stain", stain_texture(64, 10), SamplerKind::Clamp));
    const std::array<Decal, 15> decals = {{
        {"poster_far_left", far_wall(), {2, 3, 1, 2}, red},
        {"poster_far_right", far_wall(), {6, 7, 1, 2}, blue},
        {"poster_far_high", far_wall(), {4, 5, 3, 4}, red},
        {"poster_left_0", left_wall(), {3, 4, 1, 2}, blue},
        {"poster_left_1", left_wall(), {8, 9, 1, 2}, red},
        {"poster_left_2", left_wall(), {13, 14, 4, 5}, blue},
        {"poster_right_0", right_wall(), {4, 5, 1, 2}, red},
        {"poster_right_1", right_wall(), {9, 10, 4, 5}, blue},
        {"poster_right_2", right_wall(), {14, 15, 1, 2}, red},
        {"poster_near", near_wall(), {4, 5, 1, 2}, blue},
        {"stain_0", ground(), {2, 3, 2, 3}, stain},
        {"stain_1", ground(), {5, 6, 7, 8}, stain},
        {"stain_2", ground(), {6, 7, 12, 13}, stain},
        {"stain_3", ground(), {3, 4, 15, 16}, stain},
        {"stain_4", ground(), {0, 1, 5, 6}, stain},  // in the left gallery
    }};
    for (const Decal& d : decals) {
        const std::string name = std::string("decal_") + d.name;
        b.add_node(name, b.add_mesh(name, surface_mesh(d.surface, d.cells, 0.0f), d.material));
    }
}

}  // namespace

void add_dressing(ModelBuilder& b, const Materials& m) {
    add_curtains(b);
    add_planters(b, m);
    add_decals(b);
    // Head height at the near end, looking down the long axis: columns, arches, curtains and
    // foliage all stack up in depth, for a depth complexity above 3.
    CameraSpec cam;
    cam.yfov = 0.8f;
    cam.znear = 0.1f;
    cam.zfar = 200.0f;
    b.add_camera("camera", cam, {0.0f, 1.7f, kHalfLength - 2.0f}, {0.0f, 5.0f, -kHalfLength});
}

}  // namespace ds::scene::builtin::atrium
