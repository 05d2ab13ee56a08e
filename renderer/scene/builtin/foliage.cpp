// foliage: alpha-masked cards for alpha-cutoff tuning. Every card's alpha ramps from 0 at its
// left edge to 1 at its right edge (scene_facts.h), some also cut to a leaf shape, so moving
// alphaCutoff moves a visible edge across each card. Cards overlap in depth, as grass does.
// The far bushes are grass (thin blades, grass_texture): box-filtered mips average their
// alpha away, so they thin out with distance (alpha_mip_coverage).
#include <array>
#include <numbers>
#include <string>

#include "renderer/scene/builtin/angles.h"
#include "renderer/scene/builtin/gltf_builder.h"
#include "renderer/scene/builtin/scene_facts.h"
#include "renderer/scene/builtin/scenes.h"

namespace ds::scene::builtin {

namespace {

int card_material(ModelBuilder& b, const char* name, int texture) {
    MaterialSpec s;
    s.name = name;
    s.base_color_texture = texture;
    s.roughness = 0.7f;
    s.alpha = Alpha::Mask;
    s.alpha_cutoff = facts::kFoliageAlphaCutoff;
    s.double_sided = true;
    return b.add_material(s);
}

void add_ground_and_backdrop(ModelBuilder& b) {
    MaterialSpec ground;
    ground.name = "ground";
    ground.base_color_texture = b.add_texture(
        "foliage_ground", checker_texture(64, 8, {0.35f, 0.3f, 0.2f}, {0.42f, 0.37f, 0.26f}));
    ground.roughness = 0.95f;
    const int plane =
        b.add_mesh("ground", make_quad({40.0f, 40.0f}, {10.0f, 10.0f}), b.add_material(ground));
    MaterialSpec wall;
    wall.name = "backdrop";
    wall.base_color = {0.55f, 0.65f, 0.8f, 1.0f};
    const int backdrop = b.add_mesh("backdrop", make_quad({40.0f, 12.0f}), b.add_material(wall));
    b.add_node("backdrop", backdrop, {{0.0f, 6.0f, -16.0f}});
    b.add_node("ground", plane, {{}, glm::angleAxis(-kPi * 0.5f, glm::vec3(1.0f, 0.0f, 0.0f))});
}

}  // namespace

tinygltf::Model build_foliage(const Settings& /*settings*/) {
    ModelBuilder b;
    add_ground_and_backdrop(b);
    const int ramp = card_material(
        b, "alpha_ramp", b.add_texture("foliage_ramp", alpha_gradient_texture(128, false)));
    const int leaf =
        card_material(b, "alpha_ramp_leaf",
                      b.add_texture("foliage_ramp_leaf", alpha_gradient_texture(128, true)));
    MeshData card = make_quad({2.0f, 2.0f});
    for (glm::vec3& p : card.positions) p.y += 1.0f;  // stands on the ground
    const int flat_card = b.add_mesh("ramp_card", card, ramp);
    const int leaf_card = b.add_mesh("leaf_card", card, leaf);
    const int grass =
        card_material(b, "grass", b.add_texture("foliage_grass", grass_texture(128, 11)));
    const int bush = b.add_mesh("grass_bush", make_plant_cards(1.0f, 2.0f, 3, 4), grass);

    // Far to near: grass bushes, then leaf cards, then flat cards facing the camera (the
    // easiest place to read the cutoff edge), some turned to show the ramp at an angle.
    for (int i = 0; i < 7; ++i) {
        const float x = -6.0f + 2.0f * static_cast<float>(i);
        b.add_node("bush_" + std::to_string(i), bush,
                   {{x, 0.0f, -10.0f - 0.7f * static_cast<float>(i % 2)}, yaw(0.4f * i)});
    }
    const std::array<float, 5> turns = {-0.6f, -0.3f, 0.0f, 0.3f, 0.6f};
    for (size_t i = 0; i < turns.size(); ++i) {
        const float x = -5.0f + 2.5f * static_cast<float>(i);
        b.add_node("leaf_card_" + std::to_string(i), leaf_card, {{x, 0.0f, -6.5f}, yaw(turns[i])});
        b.add_node("leaf_card_back_" + std::to_string(i), leaf_card,
                   {{x + 1.0f, 0.0f, -7.5f}, yaw(-turns[i])});
    }
    for (size_t i = 0; i < turns.size(); ++i) {
        const float x = -4.4f + 2.2f * static_cast<float>(i);
        b.add_node("ramp_card_" + std::to_string(i), flat_card,
                   {{x, 0.0f, -3.0f}, yaw(turns[i] * (i % 2 ? 1.0f : 0.0f))});
    }
    CameraSpec cam;
    cam.yfov = 0.9f;
    cam.znear = 0.1f;
    cam.zfar = 100.0f;
    b.add_camera("camera", cam, {0.0f, 1.6f, 4.0f}, {0.0f, 1.0f, -6.0f});
    return b.finish("foliage");
}

}  // namespace ds::scene::builtin
