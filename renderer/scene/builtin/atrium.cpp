// atrium: a Sponza-like courtyard with two floors of arcades. It exists to give the prepass
// real overdraw (columns in front of arches in front of gallery walls, foliage, curtains) and
// the decals that broke the EQUAL test in seed 004.
#include <numbers>
#include <string>

#include "renderer/scene/builtin/angles.h"
#include "renderer/scene/builtin/atrium_layout.h"
#include "renderer/scene/builtin/scenes.h"

namespace ds::scene::builtin {

namespace atrium {

namespace {

constexpr float kWallThickness = 0.5f;

float column_z(int k) {
    return -kHalfLength + kBay * static_cast<float>(k);
}

MeshData column_mesh() {
    // The plinth is sunk kEmbed into what the column stands on, so its base never lies in
    // another surface's plane (lint: COPLANAR_OVERLAP with the end walls' boxes).
    MeshData m = make_box({-0.45f, -kEmbed, -0.45f}, {0.45f, 0.3f, 0.45f}, 1.0f);  // plinth
    MeshData shaft = make_frustum(0.32f, 0.27f, kColumnHeight - 0.6f, 20, 2.0f);
    for (glm::vec3& p : shaft.positions) p.y += 0.3f;
    m.append(shaft);
    m.append(make_box({-0.42f, kColumnHeight - 0.3f, -0.42f}, {0.42f, kColumnHeight, 0.42f},
                      1.0f));  // capital
    return m;
}

// Wall: the grid inner face plus a box behind it (for shadows); identity node transform so
// decals on it can share its exact vertices.
MeshData wall_mesh(const Surface& s) {
    MeshData m = surface_mesh(s, {0, s.cells_u, 0, s.cells_v}, 0.5f);
    const glm::vec3 n = glm::normalize(glm::cross(s.axis_u, s.axis_v));
    const glm::vec3 far_corner = s.origin + s.axis_u * (kWallCell * static_cast<float>(s.cells_u)) +
                                 s.axis_v * (kWallCell * static_cast<float>(s.cells_v)) -
                                 n * kWallThickness;
    const glm::vec3 lo = glm::min(s.origin, far_corner), hi = glm::max(s.origin, far_corner);
    // Leave out the box face that coincides with the grid face.
    uint32_t skip = 0;
    if (n.x > 0.5f) skip = kFacePosX;
    if (n.x < -0.5f) skip = kFaceNegX;
    if (n.y > 0.5f) skip = kFacePosY;
    if (n.z > 0.5f) skip = kFacePosZ;
    if (n.z < -0.5f) skip = kFaceNegZ;
    m.append(make_box(lo, hi, 0.5f, skip));
    return m;
}

void add_shell(ModelBuilder& b, const Materials& m) {
    // Authored far to near (never front to back), so a depth test alone leaves overdraw.
    b.add_node("far_wall", b.add_mesh("far_wall", wall_mesh(far_wall()), m.brick));
    b.add_node("left_wall", b.add_mesh("left_wall", wall_mesh(left_wall()), m.brick));
    b.add_node("right_wall", b.add_mesh("right_wall", wall_mesh(right_wall()), m.brick));
    b.add_node("near_wall", b.add_mesh("near_wall", wall_mesh(near_wall()), m.brick));
    b.add_node("floor", b.add_mesh("floor", wall_mesh(ground()), m.floor));

    // Gallery ceilings / upper floors and the gallery roofs, one mesh each, mirrored by nodes.
    const float inner = kArcadeX + kArchDepth * 0.5f;
    const int slab = b.add_mesh("gallery_slab",
                                make_box({inner, kUpperFloor - 0.3f, -kHalfLength},
                                         {kOuterX, kUpperFloor + kEmbed, kHalfLength}, 0.5f),
                                m.plaster);
    const int roof = b.add_mesh("gallery_roof",
                                make_box({kArcadeX - 0.4f, kRoofBottom, -kHalfLength},
                                         {kOuterX, kRoofBottom + 0.3f, kHalfLength}, 0.5f),
                                m.plaster);
    for (float side : {-1.0f, 1.0f}) {
        const Transform mirror{{}, side < 0.0f ? yaw(2.0f * kHalfPi) : glm::quat(1, 0, 0, 0)};
        b.add_node(side < 0 ? "gallery_slab_left" : "gallery_slab_right", slab, mirror);
        b.add_node(side < 0 ? "gallery_roof_left" : "gallery_roof_right", roof, mirror);
    }
}

struct ArcadeMeshes {
    int column = -1;
    int arch = -1;
};

ArcadeMeshes add_arcades(ModelBuilder& b, const Materials& m) {
    const int column = b.add_mesh("column", column_mesh(), m.marble);
    const int arch =
        b.add_mesh("arch", make_arch(kBay, kArchHeight, kArchDepth, 1.6f, 24), m.sandstone);
    const glm::vec3 upper_column_scale(0.8f, kUpperScale, 0.8f);
    const glm::vec3 upper_arch_scale(1.0f, kUpperArchScale, 0.8f);
    for (int k = 0; k <= kBays; ++k) {
        for (float side : {-1.0f, 1.0f}) {
            const std::string tag = std::to_string(k) + (side < 0 ? "_left" : "_right");
            const float x = side * kArcadeX, z = column_z(k);
            b.add_node("column_" + tag, column, {{x, 0.0f, z}});
            b.add_node("upper_column_" + tag, column,
                       {{x, kUpperFloor, z}, glm::quat(1, 0, 0, 0), upper_column_scale});
        }
    }
    for (int k = 0; k < kBays; ++k) {
        for (float side : {-1.0f, 1.0f}) {
            const std::string tag = std::to_string(k) + (side < 0 ? "_left" : "_right");
            const float x = side * kArcadeX, z = column_z(k) + kBay * 0.5f;
            b.add_node("arch_" + tag, arch, {{x, kColumnHeight, z}, yaw(kHalfPi)});
            b.add_node("upper_arch_" + tag, arch,
                       {{x, kUpperSpringing, z}, yaw(kHalfPi), upper_arch_scale});
        }
    }
    // Transverse arches across both galleries at every inner column line (Sponza's vaulted
    // bays). Seen down the long axis they stack up many layers deep.
    const float inner = kArcadeX + kArchDepth * 0.5f;
    const float span_scale = (kOuterX - inner) / kBay;
    const float centre = (kOuterX + inner) * 0.5f;
    for (int k = 1; k < kBays; ++k) {
        for (float side : {-1.0f, 1.0f}) {
            const std::string tag = std::to_string(k) + (side < 0 ? "_left" : "_right");
            const float x = side * centre, z = column_z(k);
            b.add_node("gallery_arch_" + tag, arch,
                       {{x, kColumnHeight, z}, glm::quat(1, 0, 0, 0), {span_scale, 1.0f, 1.0f}});
            b.add_node("upper_gallery_arch_" + tag, arch,
                       {{x, kUpperSpringing, z},
                        glm::quat(1, 0, 0, 0),
                        {span_scale, kUpperArchScale, 0.8f}});
        }
    }
    return {column, arch};
}

// A two-storey loggia across the far end (three bays between the side arcades), in front of
// the far wall: one more layer in the middle of the default view, as Sponza's end walls have.
void add_far_loggia(ModelBuilder& b, const Materials& m, const ArcadeMeshes& arcade) {
    const float z = -kHalfLength + 2.0f;
    const float bay = 2.0f * kArcadeX / 3.0f;
    const glm::vec3 upper_column_scale(0.8f, kUpperScale, 0.8f);
    for (float x : {-0.5f * bay, 0.5f * bay}) {
        const std::string tag = x < 0.0f ? "left" : "right";
        b.add_node("loggia_column_" + tag, arcade.column, {{x, 0.0f, z}});
        b.add_node("loggia_upper_column_" + tag, arcade.column,
                   {{x, kUpperFloor, z}, glm::quat(1, 0, 0, 0), upper_column_scale});
    }
    const float scale = bay / kBay;
    // kEmbed lower than the side arcades' arches, whose ends they meet at the corners, so the
    // two tops never share a plane there.
    const float lower_y = (kArchHeight - kEmbed) / kArchHeight;
    const float upper_y = (2.0f - kEmbed) / kArchHeight;
    for (int i = 0; i < 3; ++i) {
        const float x = (static_cast<float>(i) - 1.0f) * bay;
        b.add_node("loggia_arch_" + std::to_string(i), arcade.arch,
                   {{x, kColumnHeight, z}, glm::quat(1, 0, 0, 0), {scale, lower_y, 1.0f}});
        b.add_node("loggia_upper_arch_" + std::to_string(i), arcade.arch,
                   {{x, kUpperSpringing, z}, glm::quat(1, 0, 0, 0), {scale, upper_y, 0.8f}});
    }
    // The floor and roof stop 2 kEmbed behind the arches' face, so the two faces never share
    // the plane z = front (a band of Z-fighting across the loggia, seen from the courtyard).
    const float front = z + kArchDepth * 0.5f - 2.0f * kEmbed;
    b.add_node("loggia_floor", b.add_mesh("loggia_floor",
                                          make_box({-kArcadeX, kUpperFloor - 0.3f, -kHalfLength},
                                                   {kArcadeX, kUpperFloor + kEmbed, front}, 0.5f),
                                          m.plaster));
    b.add_node("loggia_roof",
               b.add_mesh("loggia_roof",
                          make_box({-kArcadeX, kRoofBottom - kEmbed, -kHalfLength},
                                   {kArcadeX, kRoofBottom + 0.3f + kEmbed, front}, 0.5f),
                          m.plaster));
}

void add_upper_gallery(ModelBuilder& b, const Materials& m) {
    const int parapet = b.add_mesh(
        "parapet", make_box({-0.15f, 0.0f, -kHalfLength}, {0.15f, 1.0f, kHalfLength}, 0.5f),
        m.sandstone);
    b.add_node("parapet_left", parapet, {{-kArcadeX, kUpperFloor, 0.0f}});
    b.add_node("parapet_right", parapet, {{kArcadeX, kUpperFloor, 0.0f}});
    // Ceiling beams across the upper galleries, every 2 m.
    const float inner = kArcadeX + kArchDepth * 0.5f;
    const int beam =
        b.add_mesh("beam", make_box({inner, -0.3f, -0.12f}, {kOuterX, 0.0f, 0.12f}, 1.0f), m.wood);
    for (int k = 0; k < 18; ++k) {
        const float z = -kHalfLength + 1.0f + 2.0f * static_cast<float>(k);
        b.add_node("beam_left_" + std::to_string(k), beam,
                   {{0.0f, kRoofBottom, z}, yaw(2.0f * kHalfPi)});
        b.add_node("beam_right_" + std::to_string(k), beam, {{0.0f, kRoofBottom, z}});
    }
}

}  // namespace

Surface far_wall() {
    return {{-kOuterX, 0, -kHalfLength}, {1, 0, 0}, {0, 1, 0}, 9, 6};
}
Surface near_wall() {
    return {{kOuterX, 0, kHalfLength}, {-1, 0, 0}, {0, 1, 0}, 9, 6};
}
Surface left_wall() {
    return {{-kOuterX, 0, kHalfLength}, {0, 0, -1}, {0, 1, 0}, 18, 6};
}
Surface right_wall() {
    return {{kOuterX, 0, -kHalfLength}, {0, 0, 1}, {0, 1, 0}, 18, 6};
}
Surface ground() {
    return {{-kOuterX, 0, kHalfLength}, {1, 0, 0}, {0, 0, -1}, 9, 18};
}

MeshData surface_mesh(const Surface& s, GridRange range, float uv_per_meter) {
    return make_grid(s.origin, s.axis_u, s.axis_v, {kWallCell, kWallCell}, range, uv_per_meter);
}

Materials add_materials(ModelBuilder& b) {
    Materials m;
    auto textured = [&](const char* name, int texture, glm::vec4 factor, float roughness) {
        MaterialSpec s;
        s.name = name;
        s.base_color = factor;
        s.base_color_texture = texture;
        s.roughness = roughness;
        return s;
    };
    const glm::vec4 white(1.0f);
    m.floor = b.add_material(
        textured("stone_floor",
                 b.add_texture("atrium_tiles", stone_tile_texture(128, {0.62f, 0.58f, 0.5f}, 1)),
                 white, 0.7f));
    MaterialSpec brick =
        textured("brick_wall",
                 b.add_texture("atrium_brick",
                               brick_texture(128, {0.6f, 0.28f, 0.18f}, {0.75f, 0.72f, 0.66f}, 2)),
                 white, 0.9f);
    brick.normal_texture = b.add_texture("atrium_brick_normal", brick_normal_map(128));
    m.brick = b.add_material(brick);
    m.marble = b.add_material(textured(
        "column_marble",
        b.add_texture("atrium_marble", marble_texture(128, {0.9f, 0.87f, 0.8f}, 3)), white, 0.35f));
    const int sandstone_tex =
        b.add_texture("atrium_sandstone", sandstone_texture(128, {0.8f, 0.68f, 0.5f}, 4));
    m.sandstone = b.add_material(textured("arch_sandstone", sandstone_tex, white, 0.8f));
    m.plaster =
        b.add_material(textured("plaster", sandstone_tex, {0.95f, 0.93f, 0.88f, 1.0f}, 0.9f));
    m.wood =
        b.add_material(textured("wood_beams",
                                b.add_texture("atrium_wood", wood_texture(128, {0.55f, 0.36f, 0.2f},
                                                                          {0.3f, 0.18f, 0.09f}, 5)),
                                white, 0.6f));
    m.terracotta = b.add_material(textured("terracotta", -1, {0.72f, 0.36f, 0.22f, 1.0f}, 0.85f));
    return m;
}

}  // namespace atrium

tinygltf::Model build_atrium(const Settings& /*settings*/) {
    ModelBuilder b;
    atrium::Materials m = atrium::add_materials(b);
    atrium::add_shell(b, m);
    const atrium::ArcadeMeshes arcade = atrium::add_arcades(b, m);
    atrium::add_far_loggia(b, m, arcade);
    atrium::add_upper_gallery(b, m);
    atrium::add_dressing(b, m);  // curtains, planters, foliage, decals, camera
    return b.finish("atrium");
}

}  // namespace ds::scene::builtin
