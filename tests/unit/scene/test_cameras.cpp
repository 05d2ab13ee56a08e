// Every camera node the importer keeps (Scene::cameras: what `depthscope cameras` lists and
// --camera picks).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

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

}  // namespace
}  // namespace ds::scene
