// Buried overlays (decals.h): a surface just behind another that faces the same way, as a
// quantizing compressor leaves a decal, on hand-made quads 18 m from the origin (the atrium's
// far wall). The Draco-compressed atrium's posters: compressed_tests.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/scene/decals.h"

namespace ds::scene {
namespace {

// The rectangle [x0, x1] x [y0, y1] in the plane z, facing +Z (or -Z when `back`).
Mesh quad(float x0, float x1, float y0, float y1, float z, bool back = false) {
    Mesh m;
    for (const glm::vec3 p :
         {glm::vec3(x0, y0, z), glm::vec3(x1, y0, z), glm::vec3(x1, y1, z), glm::vec3(x0, y1, z)})
        m.vertices.push_back({p});
    m.indices =
        back ? std::vector<uint32_t>{0, 2, 1, 0, 3, 2} : std::vector<uint32_t>{0, 1, 2, 0, 2, 3};
    return m;
}

// The wall (instance 0) and `top` (instance 1), both moved 18 m along -Z.
OverlayClasses classify(const Mesh& top) {
    const std::vector<Mesh> meshes = {quad(-9, 9, 0, 12, 0), top};
    const glm::mat4 far = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -18));
    return classify_overlays(meshes, {{0, far, ""}, {1, far, ""}});
}

TEST(BuriedOverlays, APosterAMillimetreBehindItsWallIsBuriedWithItsGap) {
    const OverlayClasses c = classify(quad(-5, -3, 2, 4, -0.00122f));
    EXPECT_EQ(c.decal_base, (std::vector<int32_t>{-1, -1}));
    ASSERT_EQ(c.buried.size(), 1u);
    EXPECT_EQ(c.buried[0].instance, 1u);
    EXPECT_EQ(c.buried[0].base, 0u);
    EXPECT_NEAR(c.buried[0].gap, 0.00122, 1e-5);
}

TEST(BuriedOverlays, OnTheWallItIsADecalAndInFrontOfItNothing) {
    const OverlayClasses on = classify(quad(-5, -3, 2, 4, 0.0f));
    EXPECT_EQ(on.decal_base, (std::vector<int32_t>{-1, 0}));
    EXPECT_TRUE(on.buried.empty());
    const OverlayClasses front = classify(quad(-5, -3, 2, 4, 0.00122f));
    EXPECT_EQ(front.decal_base, (std::vector<int32_t>{-1, -1}));
    EXPECT_TRUE(front.buried.empty());
}

// A wall with thickness: the poster lies inside the box, behind its front face.
TEST(BuriedOverlays, BehindTheFrontFaceOfAThickWall) {
    Mesh wall = quad(-9, 9, 0, 12, 0);
    const Mesh back = quad(-9, 9, 0, 12, -0.5f, /*back=*/true);
    for (const uint32_t i : back.indices) wall.indices.push_back(i + 4);
    for (const Vertex& v : back.vertices) wall.vertices.push_back(v);
    const std::vector<Mesh> meshes = {wall, quad(-5, -3, 2, 4, -0.00122f)};
    const glm::mat4 far = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -17.99878f));
    const OverlayClasses c = classify_overlays(meshes, {{0, far, ""}, {1, far, ""}});
    ASSERT_EQ(c.buried.size(), 1u);
    EXPECT_NEAR(c.buried[0].gap, 0.00122, 1e-5);
}

TEST(BuriedOverlays, FacingAwayFarBehindOrOverTheEdgeIsNot) {
    EXPECT_TRUE(classify(quad(-5, -3, 2, 4, -0.00122f, /*back=*/true)).buried.empty());
    EXPECT_TRUE(classify(quad(-5, -3, 2, 4, -0.1f)).buried.empty());  // 10 cm: another surface
    EXPECT_TRUE(classify(quad(8, 10, 2, 4, -0.00122f)).buried.empty());
}

}  // namespace
}  // namespace ds::scene
