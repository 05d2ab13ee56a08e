// The scene model's own logic: names, camera view, triangle counts, framing.
#include <cmath>

#include <gtest/gtest.h>

#include "renderer/scene/scene.h"

namespace ds::scene {
namespace {

TEST(SceneModel, AlphaModeNames) {
    EXPECT_STREQ(to_string(AlphaMode::Opaque), "opaque");
    EXPECT_STREQ(to_string(AlphaMode::Mask), "mask");
    EXPECT_STREQ(to_string(AlphaMode::Blend), "blend");
}

TEST(SceneModel, ViewMapsCameraToOriginLookingDownMinusZ) {
    Camera c;
    c.position = {1, 2, 3};
    c.forward = {1, 0, 0};
    c.up = {0, 1, 0};
    const glm::mat4 v = c.view();
    const glm::vec4 eye = v * glm::vec4(c.position, 1.0f);
    EXPECT_NEAR(glm::length(glm::vec3(eye)), 0.0f, 1e-5f);
    const glm::vec4 ahead = v * glm::vec4(c.position + c.forward, 1.0f);
    EXPECT_NEAR(ahead.z, -1.0f, 1e-5f);
    EXPECT_NEAR(ahead.x, 0.0f, 1e-5f);
}

TEST(SceneModel, TriangleCountIsOverInstances) {
    Scene s;
    s.meshes.resize(2);
    s.meshes[0].indices.assign(6, 0);  // 2 triangles
    s.meshes[1].indices.assign(9, 0);  // 3 triangles
    s.instances = {{0, glm::mat4(1), "a"}, {0, glm::mat4(1), "b"}, {1, glm::mat4(1), "c"}};
    EXPECT_EQ(s.triangle_count(), 2u + 2u + 3u);
}

TEST(SceneModel, FrameBoundsKeepsTheWholeBoxInView) {
    Bounds b;
    b.extend(glm::vec3(-10, 0, -4));
    b.extend(glm::vec3(30, 5, 8));
    const float yfov = 0.8f;
    const Camera c = frame_bounds(b, yfov);
    EXPECT_FLOAT_EQ(c.yfov, yfov);
    EXPECT_NEAR(glm::length(c.forward), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::length(c.up), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(c.forward, c.up), 0.0f, 1e-5f);
    // Looks at the centre, from above and in front (a 3/4 view, not axis-aligned).
    const glm::vec3 to_center = glm::normalize(b.center() - c.position);
    EXPECT_GT(glm::dot(to_center, c.forward), 0.9999f);
    EXPECT_LT(c.forward.y, -0.1f);
    EXPECT_GT(std::abs(c.forward.x), 0.1f);
    // Every corner lies inside the vertical field of view (square aspect) and the depth range.
    const glm::mat4 view = c.view();
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 p{(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y,
                          (i & 4) ? b.max.z : b.min.z};
        const glm::vec3 q = glm::vec3(view * glm::vec4(p, 1.0f));
        const float depth = -q.z;
        EXPECT_GT(depth, c.znear);
        EXPECT_LT(depth, c.zfar);
        EXPECT_LE(std::abs(q.y) / depth, std::tan(yfov * 0.5f));
        EXPECT_LE(std::abs(q.x) / depth, std::tan(yfov * 0.5f));
    }
}

TEST(SceneModel, FrameBoundsOfNothingIsTheDefaultCamera) {
    const Camera c = frame_bounds(Bounds{});
    EXPECT_EQ(c.position, Camera{}.position);
    EXPECT_EQ(c.forward, Camera{}.forward);
}

TEST(SceneModel, FrameBoundsOfAPointStaysFinite) {
    Bounds b;
    b.extend(glm::vec3(1, 2, 3));
    const Camera c = frame_bounds(b);
    EXPECT_TRUE(std::isfinite(c.position.x) && std::isfinite(c.zfar));
    EXPECT_GT(c.zfar, c.znear);
}

}  // namespace
}  // namespace ds::scene

namespace ds::scene {
namespace {

// A scene of boxes: each (min, max) a mesh of its own placed once, scaled from a unit box by
// its instance's transform (content_bounds reads mesh bounds through instance transforms).
Scene boxes(const std::vector<std::pair<glm::vec3, glm::vec3>>& list) {
    Scene s;
    s.meshes.resize(1);
    s.meshes[0].bounds.extend(glm::vec3(0.0f));
    s.meshes[0].bounds.extend(glm::vec3(1.0f));
    for (const auto& [lo, hi] : list) {
        glm::mat4 world(1.0f);
        world[0][0] = hi.x - lo.x;
        world[1][1] = hi.y - lo.y;
        world[2][2] = hi.z - lo.z;
        world[3] = glm::vec4(lo, 1.0f);
        s.instances.push_back({0, world, "box"});
        s.bounds.extend(lo);
        s.bounds.extend(hi);
    }
    return s;
}

void expect_box(const Bounds& b, glm::vec3 lo, glm::vec3 hi) {
    for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(b.min[a], lo[a], 1e-3f) << "axis " << a;
        EXPECT_NEAR(b.max[a], hi[a], 1e-3f) << "axis " << a;
    }
}

TEST(ContentBounds, AGroundPlaneThatDwarfsTheSubjectIsLeftOut) {
    const Scene s = boxes({{{-500, -0.1f, -500}, {500, 0, 500}},  // ground
                           {{-1, 0, -1}, {1, 2, 1}},
                           {{2, 0, 0}, {3, 1, 1}}});
    expect_box(content_bounds(s), {-1, 0, -1}, {3, 2, 1});
}

TEST(ContentBounds, AGroundAndABackdropBothGo) {
    const Scene s = boxes({{{-500, -0.1f, -500}, {500, 0, 500}},  // ground
                           {{-500, 0, -501}, {500, 400, -500}},   // backdrop wall
                           {{-1, 0, -1}, {1, 2, 1}},
                           {{0, 0, 2}, {1, 1, 3}}});
    expect_box(content_bounds(s), {-1, 0, -1}, {1, 2, 3});
}

// The foliage scene's shape: a 40 x 40 ground and a 40 x 12 backdrop around plants that fill
// a third of the whole box's diagonal.
TEST(ContentBounds, PlantsOnAGroundBeforeABackdrop) {
    const Scene s = boxes({{{-20, -0.1f, -20}, {20, 0, 20}},
                           {{-20, 0, -16.1f}, {20, 12, -16}},
                           {{-8, 0, -7}, {8, 2, 0}},
                           {{-2, 0, -3}, {2, 1.5f, -1}}});
    expect_box(content_bounds(s), {-8, 0, -7}, {8, 2, 0});
}

TEST(ContentBounds, ARoomIsItsWholeBox) {
    // Floor, four walls and furniture: the largest parts are the room itself.
    const Scene s = boxes({{{-10, -0.1f, -6}, {10, 0, 6}},
                           {{-10, 0, -6.1f}, {10, 8, -6}},
                           {{-10, 0, 6}, {10, 8, 6.1f}},
                           {{-10.1f, 0, -6}, {-10, 8, 6}},
                           {{10, 0, -6}, {10.1f, 8, 6}},
                           {{-1, 0, -1}, {1, 1, 1}},
                           {{3, 0, 2}, {4, 2, 3}}});
    expect_box(content_bounds(s), s.bounds.min, s.bounds.max);
}

TEST(ContentBounds, ASingleInstanceOrNoneIsTheSceneBounds) {
    const Scene one = boxes({{{-500, -0.1f, -500}, {500, 0, 500}}});
    expect_box(content_bounds(one), one.bounds.min, one.bounds.max);
    EXPECT_FALSE(content_bounds(Scene{}).valid());
}

}  // namespace
}  // namespace ds::scene
