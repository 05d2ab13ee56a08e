// Every camera node the importer keeps (Scene::cameras: what `depthscope cameras` lists and
// --camera picks), and "fit inside" (scene/fit_inside.h) on hand-made rooms: the eye in an
// open gap above a floor, looking along the longest horizontal axis to the freer side.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "renderer/scene/fit_inside.h"
#include "renderer/scene/importer.h"
#include "tests/unit/scene/model_builder.h"

namespace ds::scene {
namespace {

const std::filesystem::path kCameras =
    std::filesystem::path(DS_SOURCE_DIR) / "tests/data/cameras.gltf";

void expect_near(const glm::vec3& a, const glm::vec3& b) {
    EXPECT_NEAR(glm::length(a - b), 0.0f, 1e-5f) << a.x << "," << a.y << "," << a.z;
}

TEST(SceneCameras, EveryCameraNodeInWalkOrderThePerspectiveOnesPlaced) {
    const Scene s = load_gltf(kCameras);
    ASSERT_EQ(s.cameras.size(), 3u);
    const SceneCamera& front = s.cameras[0];
    EXPECT_EQ(front.name, "Front");
    EXPECT_EQ(front.gltf_node, 1);
    EXPECT_EQ(front.type, SceneCamera::Type::Perspective);
    EXPECT_FLOAT_EQ(front.yfov, 0.8f);
    EXPECT_FLOAT_EQ(front.zfar, 100.0f);
    ASSERT_TRUE(front.camera && s.file_camera);
    EXPECT_EQ(*front.camera, *s.file_camera);  // the first perspective camera is the file's
    EXPECT_EQ(s.camera, *s.file_camera);

    const SceneCamera& side = s.cameras[1];  // under "Parent" (translated by 5 in X)
    EXPECT_EQ(side.name, "Side");
    EXPECT_EQ(side.gltf_node, 3);
    EXPECT_EQ(side.zfar, 0.0f);  // none in the file: infinite
    ASSERT_TRUE(side.camera);
    expect_near(side.camera->position, {8, 1, 0});
    expect_near(side.camera->forward, {-1, 0, 0});
    expect_near(side.camera->up, {0, 1, 0});
    EXPECT_GT(side.camera->zfar, 20.0f);  // finite, past the scene

    const SceneCamera& top = s.cameras[2];
    EXPECT_EQ(top.name, "Top");
    EXPECT_EQ(top.type, SceneCamera::Type::Orthographic);
    EXPECT_FALSE(top.camera);
    EXPECT_FLOAT_EQ(top.znear, 0.1f);
    EXPECT_FLOAT_EQ(top.zfar, 50.0f);
    EXPECT_STREQ(to_string(top.type), "orthographic");
}

TEST(SceneCameras, ACameraNodeWithoutAViewDirectionIsListedUnplaced) {
    test::ModelBuilder b;
    tinygltf::Camera persp;
    persp.type = "perspective";
    persp.perspective.yfov = 0.5;
    persp.perspective.znear = 0.1;
    b.model.cameras = {persp};
    b.add_node(b.add_quad_mesh());
    const int flat = b.add_node(-1, {0, 0, 5});
    b.model.nodes[size_t(flat)].camera = 0;
    b.model.nodes[size_t(flat)].scale = {1, 1, 0};  // -Z collapses
    b.model.nodes[size_t(b.add_node(-1, {0, 0, 4}))].camera = 0;
    const Scene s = import_model(b.model, "t", "mem:t");
    ASSERT_EQ(s.cameras.size(), 2u);
    EXPECT_FALSE(s.cameras[0].camera);
    ASSERT_TRUE(s.cameras[1].camera && s.file_camera);
    EXPECT_EQ(s.file_camera->position, glm::vec3(0, 0, 4));  // the first one placed
}

// A hand-made scene of quads (counter-clockwise seen from the front), each its own instance.
struct Room {
    Scene scene;
    void quad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, bool double_sided = false) {
        Mesh m;
        for (const glm::vec3& p : {a, b, c, d}) {
            m.vertices.push_back({p});
            m.bounds.extend(p);
        }
        m.indices = {0, 1, 2, 0, 2, 3};
        m.material = double_sided ? 1 : 0;
        Instance instance;
        instance.mesh = uint32_t(scene.meshes.size());
        scene.instances.push_back(instance);
        scene.bounds.extend(m.bounds);
        scene.meshes.push_back(std::move(m));
    }
    // A horizontal quad over x0..x1, z0..z1 at height y, facing up or down.
    void slab(float x0, float x1, float z0, float z1, float y, bool up) {
        if (up)
            quad({x0, y, z1}, {x1, y, z1}, {x1, y, z0}, {x0, y, z0});
        else
            quad({x0, y, z0}, {x1, y, z0}, {x1, y, z1}, {x0, y, z1});
    }
    Room() {
        scene.materials.resize(2);
        scene.materials[1].double_sided = true;
    }
};

// 20 x 8 (X longer than Z), 4 high: the eye 1.6 above the floor at the centre, looking along X
// to the side with more room (a partition at x = 6: the -X side is freer).
TEST(FitInside, TheEyeStandsOnTheFloorLookingAlongTheLongestAxisToTheFreerSide) {
    Room r;
    r.slab(-10, 10, -4, 4, 0, /*up=*/true);
    r.slab(-10, 10, -4, 4, 4, /*up=*/false);
    r.quad({6, 0, 4}, {6, 0, -4}, {6, 4, -4}, {6, 4, 4});  // a partition
    Camera like;
    like.yfov = 0.9f;
    like.znear = 0.05f;
    like.zfar = 1.0f;
    const Camera c = fit_inside(r.scene, like);
    expect_near(c.position, {0, kEyeHeight, 0});
    EXPECT_EQ(c.forward, glm::vec3(-1, 0, 0));
    EXPECT_EQ(c.up, glm::vec3(0, 1, 0));
    EXPECT_EQ(c.yfov, 0.9f);
    EXPECT_EQ(c.znear, 0.05f);
    EXPECT_GT(c.zfar, 10.0f);  // reaches the far walls

    Room turned;  // the same room along Z, the partition towards -Z
    turned.slab(-4, 4, -10, 10, 0, /*up=*/true);
    turned.quad({-4, 0, -6}, {4, 0, -6}, {4, 4, -6}, {-4, 4, -6});
    const Camera t = fit_inside(turned.scene, like);
    EXPECT_EQ(t.forward, glm::vec3(0, 0, 1));
    expect_near(t.position, {0, kEyeHeight, 0});  // no ceiling: up to the bounds' top
}

// Two storeys: the tallest open gap is the upper hall (the slab's inside is no gap: its lower
// face faces down), so the eye stands on the slab.
TEST(FitInside, TheTallestOpenGapWinsAndASolidsInsideIsNone) {
    Room r;
    r.slab(-10, 10, -4, 4, 0, true);       // ground floor
    r.slab(-10, 10, -4, 4, 3.0f, false);   // the slab's underside
    r.slab(-10, 10, -4, 4, 3.2f, true);    // its top
    r.slab(-10, 10, -4, 4, 10.0f, false);  // the roof
    const Camera c = fit_inside(r.scene, Camera{});
    expect_near(c.position, {0, 3.2f + kEyeHeight, 0});

    Room low;  // a crawl space 1 high: half way up
    low.slab(-10, 10, -4, 4, 0, true);
    low.slab(-10, 10, -4, 4, 1, false);
    expect_near(fit_inside(low.scene, Camera{}).position, {0, 0.5f, 0});

    Room leaf;  // a double-sided floor counts from either side
    leaf.quad({-10, 0, -4}, {10, 0, -4}, {10, 0, 4}, {-10, 0, 4}, /*double_sided=*/true);
    leaf.slab(-10, 10, -4, 4, 4, false);
    expect_near(fit_inside(leaf.scene, Camera{}).position, {0, kEyeHeight, 0});
}

// The rays themselves: front and back faces, t_max, and a mirroring transform (the winding is
// judged in world space: mirrored in Y, the quad at y = 0 is the same triangles, met from
// above on their front although the mesh's own space sees the ray come from below).
TEST(FitInside, RaysMeetFrontAndBackFaces) {
    Room r;
    r.slab(-1, 1, -1, 1, 0, true);
    const glm::vec3 above(0.5f, 5, 0.2f), below(0.5f, -5, 0.2f);  // off the shared diagonal
    const auto down = cast_ray(r.scene, above, {0, -1, 0}, 10.0f);
    ASSERT_EQ(down.size(), 1u);
    EXPECT_FLOAT_EQ(down[0].t, 5.0f);
    EXPECT_TRUE(down[0].front);
    const auto up = cast_ray(r.scene, below, {0, 1, 0}, 10.0f);
    ASSERT_EQ(up.size(), 1u);
    EXPECT_FALSE(up[0].front);
    EXPECT_TRUE(cast_ray(r.scene, above, {0, -1, 0}, 4.0f).empty());  // beyond t_max
    r.scene.instances[0].world[1][1] = -1.0f;
    const auto mirrored = cast_ray(r.scene, above, {0, -1, 0}, 10.0f);
    ASSERT_EQ(mirrored.size(), 1u);
    EXPECT_TRUE(mirrored[0].front);
}

}  // namespace
}  // namespace ds::scene
