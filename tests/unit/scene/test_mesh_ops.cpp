// Geometry fix-ups: flat normals for meshes without normals, generated tangents, bounds.
#include <cmath>

#include <gtest/gtest.h>

#include "renderer/scene/mesh_ops.h"

namespace ds::scene::detail {
namespace {

std::vector<Vertex> quad_vertices() {
    std::vector<Vertex> v(4);
    const glm::vec3 p[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const glm::vec2 uv[4] = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    for (int i = 0; i < 4; ++i) {
        v[i].position = p[i];
        v[i].uv0 = uv[i];
        v[i].normal = {0, 0, 1};
    }
    return v;
}

bool finite(const glm::vec4& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

TEST(MeshOps, UnweldGivesEachTriangleItsFaceNormal) {
    std::vector<Vertex> v = quad_vertices();
    for (Vertex& x : v) x.normal = {9, 9, 9};  // must be replaced
    std::vector<uint32_t> idx = {0, 1, 2, 0, 2, 3};
    unweld_flat_normals(v, idx);
    ASSERT_EQ(v.size(), 6u);
    ASSERT_EQ(idx, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
    for (const Vertex& x : v) EXPECT_EQ(x.normal, glm::vec3(0, 0, 1));
    EXPECT_EQ(v[3].position, glm::vec3(0, 0, 0));  // second triangle starts at old vertex 0
    EXPECT_EQ(v[5].position, glm::vec3(0, 1, 0));
}

TEST(MeshOps, UnweldOfADegenerateTriangleKeepsAUnitNormal) {
    std::vector<Vertex> v(3);  // all at the origin
    std::vector<uint32_t> idx = {0, 1, 2};
    unweld_flat_normals(v, idx);
    for (const Vertex& x : v) EXPECT_NEAR(glm::length(x.normal), 1.0f, 1e-6f);
}

TEST(MeshOps, TangentsFollowTheUDirection) {
    std::vector<Vertex> v = quad_vertices();
    generate_tangents(v, {0, 1, 2, 0, 2, 3});
    for (const Vertex& x : v) {
        EXPECT_NEAR(x.tangent.x, 1.0f, 1e-5f);
        EXPECT_NEAR(x.tangent.y, 0.0f, 1e-5f);
        EXPECT_NEAR(x.tangent.z, 0.0f, 1e-5f);
        // An unmirrored mapping (v grows downwards, glTF UV origin top-left): the bitangent
        // cross(n, t) * w must be +Y, image "up", so w = +1.
        EXPECT_EQ(x.tangent.w, 1.0f);
    }
}

TEST(MeshOps, MirroredUVsFlipHandedness) {
    std::vector<Vertex> v = quad_vertices();
    for (Vertex& x : v) x.uv0.y = 1.0f - x.uv0.y;
    generate_tangents(v, {0, 1, 2, 0, 2, 3});
    for (const Vertex& x : v) EXPECT_EQ(x.tangent.w, -1.0f);
}

TEST(MeshOps, DegenerateUVsStillGiveUnitPerpendicularTangents) {
    std::vector<Vertex> v = quad_vertices();
    for (Vertex& x : v) x.uv0 = {0.5f, 0.5f};  // no UV gradient at all
    generate_tangents(v, {0, 1, 2, 0, 2, 3});
    for (const Vertex& x : v) {
        ASSERT_TRUE(finite(x.tangent));
        EXPECT_NEAR(glm::length(glm::vec3(x.tangent)), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(glm::vec3(x.tangent), x.normal), 0.0f, 1e-5f);
        EXPECT_TRUE(x.tangent.w == 1.0f || x.tangent.w == -1.0f);
    }
}

TEST(MeshOps, ZeroNormalDoesNotProduceNaN) {
    std::vector<Vertex> v = quad_vertices();
    for (Vertex& x : v) {
        x.normal = glm::vec3(0.0f);
        x.uv0 = glm::vec2(0.0f);
    }
    generate_tangents(v, {0, 1, 2, 0, 2, 3});
    for (const Vertex& x : v) EXPECT_TRUE(finite(x.tangent));
}

TEST(MeshOps, BoundsTransformToWorld) {
    const Bounds local = compute_bounds(quad_vertices());
    EXPECT_EQ(local.min, glm::vec3(0, 0, 0));
    EXPECT_EQ(local.max, glm::vec3(1, 1, 0));
    glm::mat4 world(1.0f);
    world[3] = glm::vec4(10, 0, 0, 1);
    world[0] = glm::vec4(-2, 0, 0, 0);  // mirrored and scaled along X
    const Bounds w = transform_bounds(local, world);
    EXPECT_EQ(w.min, glm::vec3(8, 0, 0));
    EXPECT_EQ(w.max, glm::vec3(10, 1, 0));
    EXPECT_FALSE(transform_bounds(Bounds{}, world).valid());
}

}  // namespace
}  // namespace ds::scene::detail
