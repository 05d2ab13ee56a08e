// The decals scene is what scene_facts.h says: overlays made of their base's own triangles
// (bit-identical world vertices), materials and the MASK texture's split, and a camera that
// sees every overlay whole.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "model_view.h"
#include "renderer/scene/builtin/builtin.h"
#include "renderer/scene/builtin/scene_facts.h"

namespace ds::scene::builtin {
namespace {

using facts::DecalsAlpha;

const tinygltf::Model& decals() {
    static const tinygltf::Model m = build("decals", Settings());
    return m;
}

int node_index(const tinygltf::Model& m, const std::string& name) {
    for (size_t i = 0; i < m.nodes.size(); ++i)
        if (m.nodes[i].name == name) return static_cast<int>(i);
    return -1;
}

std::vector<test::WorldTriangle> triangles_of(const std::string& node) {
    std::vector<test::WorldTriangle> out;
    for (const test::WorldTriangle& t : test::world_triangles(decals()))
        if (t.node == node_index(decals(), node)) out.push_back(t);
    return out;
}

bool same_triangle(const test::WorldTriangle& a, const test::WorldTriangle& b) {
    for (int k = 0; k < 3; ++k)
        if (a.p[k] != b.p[k]) return false;  // bit-exact on purpose
    return true;
}

TEST(DecalsScene, EveryOverlayTriangleIsOneOfItsBasesTriangles) {
    for (const facts::DecalsOverlay& o : facts::kDecalsOverlays) {
        SCOPED_TRACE(o.node);
        const std::vector<test::WorldTriangle> top = triangles_of(o.node);
        const std::vector<test::WorldTriangle> base =
            triangles_of(facts::kDecalsSurfaces[o.surface].node);
        ASSERT_EQ(top.size(), static_cast<size_t>(2 * (o.i1 - o.i0) * (o.j1 - o.j0)));
        for (const test::WorldTriangle& t : top) {
            EXPECT_TRUE(std::any_of(base.begin(), base.end(),
                                    [&](const auto& b) { return same_triangle(t, b); }));
        }
    }
    // The left wall and its overlay come through the same non-identity node transform.
    const tinygltf::Node& wall = decals().nodes.at(node_index(decals(), "left_wall"));
    const tinygltf::Node& blue = decals().nodes.at(node_index(decals(), "decal_blue_blend"));
    EXPECT_FALSE(wall.rotation.empty());
    EXPECT_EQ(wall.rotation, blue.rotation);
    EXPECT_EQ(wall.translation, blue.translation);
}

// Each overlay covers exactly its fact rectangle, on the front of its surface.
TEST(DecalsScene, OverlaysCoverTheirFactRectangles) {
    for (const facts::DecalsOverlay& o : facts::kDecalsOverlays) {
        SCOPED_TRACE(o.node);
        const facts::DecalsRect r = facts::decals_overlay_rect(o);
        glm::vec2 lo(1e30f), hi(-1e30f);
        const glm::vec3 normal = glm::normalize(glm::cross(r.edge_u, r.edge_v));
        for (const test::WorldTriangle& t : triangles_of(o.node)) {
            const glm::vec3 face = glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
            EXPECT_GT(glm::dot(face, normal), 0.0f);
            for (const glm::vec3& p : t.p) {
                const glm::vec3 d = p - r.origin;
                const glm::vec2 st(glm::dot(d, r.edge_u) / glm::dot(r.edge_u, r.edge_u),
                                   glm::dot(d, r.edge_v) / glm::dot(r.edge_v, r.edge_v));
                EXPECT_NEAR(glm::dot(d, normal), 0.0f, 1e-5f);
                lo = glm::min(lo, st);
                hi = glm::max(hi, st);
            }
        }
        EXPECT_NEAR(lo.x, 0.0f, 1e-5f);
        EXPECT_NEAR(lo.y, 0.0f, 1e-5f);
        EXPECT_NEAR(hi.x, 1.0f, 1e-5f);
        EXPECT_NEAR(hi.y, 1.0f, 1e-5f);
    }
}

const tinygltf::Material& material_of(const std::string& node) {
    const tinygltf::Model& m = decals();
    const int mesh = m.nodes.at(node_index(m, node)).mesh;
    return m.materials.at(m.meshes.at(mesh).primitives.at(0).material);
}

TEST(DecalsScene, MaterialsAreAsDocumented) {
    for (const facts::DecalsSurface& s : facts::kDecalsSurfaces) {
        const tinygltf::Material& mat = material_of(s.node);
        EXPECT_EQ(mat.alphaMode, "OPAQUE");
        const auto& c = mat.pbrMetallicRoughness.baseColorFactor;
        EXPECT_FLOAT_EQ(static_cast<float>(c[0]), facts::kDecalsBaseColour.r) << s.node;
    }
    for (const facts::DecalsOverlay& o : facts::kDecalsOverlays) {
        SCOPED_TRACE(o.node);
        const tinygltf::Material& mat = material_of(o.node);
        const auto& c = mat.pbrMetallicRoughness.baseColorFactor;
        for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(static_cast<float>(c[k]), o.colour[k]);
        const char* mode = o.alpha == DecalsAlpha::Opaque ? "OPAQUE"
                           : o.alpha == DecalsAlpha::Mask ? "MASK"
                                                          : "BLEND";
        EXPECT_EQ(mat.alphaMode, mode);
        EXPECT_FLOAT_EQ(static_cast<float>(c[3]),
                        o.alpha == DecalsAlpha::Blend ? facts::kDecalsBlendAlpha : 1.0f);
        if (o.alpha == DecalsAlpha::Mask) {
            EXPECT_FLOAT_EQ(static_cast<float>(mat.alphaCutoff), facts::kDecalsMaskCutoff);
        }
        EXPECT_EQ(mat.pbrMetallicRoughness.baseColorTexture.index >= 0,
                  o.alpha == DecalsAlpha::Mask);
    }
}

// The MASK texture keeps u < kDecalsMaskKeep, and a MASK overlay's u runs from 0 to 1 with s.
TEST(DecalsScene, MaskKeepsTheDocumentedPart) {
    const tinygltf::Model& m = decals();
    for (const facts::DecalsOverlay& o : facts::kDecalsOverlays) {
        if (o.alpha != DecalsAlpha::Mask) continue;
        SCOPED_TRACE(o.node);
        const tinygltf::Material& mat = material_of(o.node);
        const tinygltf::Texture& tex =
            m.textures.at(mat.pbrMetallicRoughness.baseColorTexture.index);
        const tinygltf::Image& img = m.images.at(tex.source);
        for (int y = 0; y < img.height; y += 7) {
            for (int x = 0; x < img.width; ++x) {
                const float u = (static_cast<float>(x) + 0.5f) / static_cast<float>(img.width);
                const uint8_t a = img.image[(static_cast<size_t>(y) * img.width + x) * 4 + 3];
                ASSERT_EQ(a, u < facts::kDecalsMaskKeep ? 255 : 0) << x;
            }
        }
        const tinygltf::Primitive& prim =
            m.meshes.at(m.nodes.at(node_index(m, o.node)).mesh).primitives.at(0);
        const std::vector<glm::vec3> pos = test::read_vec3(m, prim.attributes.at("POSITION"));
        const tinygltf::Accessor& uvs = m.accessors.at(prim.attributes.at("TEXCOORD_0"));
        const tinygltf::BufferView& view = m.bufferViews.at(uvs.bufferView);
        ASSERT_EQ(uvs.count, pos.size());
        ASSERT_EQ(view.byteStride, 0u);  // tightly packed vec2
        const facts::DecalsRect r = facts::decals_overlay_rect(o);
        for (size_t i = 0; i < pos.size(); ++i) {
            glm::vec2 uv;
            std::memcpy(&uv,
                        m.buffers.at(view.buffer).data.data() + view.byteOffset + uvs.byteOffset +
                            i * sizeof(uv),
                        sizeof(uv));
            const float s = glm::dot(pos[i] - r.origin, r.edge_u) / glm::dot(r.edge_u, r.edge_u);
            EXPECT_NEAR(uv.x, s, 1e-6f);  // authored in world space: no node transform
        }
    }
}

// Every overlay corner well inside the view at 16:9 (so at 320x180 too), in front of the
// camera, facing it at less than 70 degrees, and big enough to read by hue at 320x180.
TEST(DecalsScene, CameraSeesEveryOverlayWhole) {
    const auto cam = test::find_camera(decals());
    ASSERT_TRUE(cam.has_value());
    EXPECT_FLOAT_EQ(cam->aspect, 16.0f / 9.0f);
    const glm::mat4 proj = glm::perspective(cam->yfov, 16.0f / 9.0f, cam->znear, cam->zfar);
    const glm::vec3 eye = glm::vec3(glm::inverse(cam->view)[3]);
    for (const facts::DecalsOverlay& o : facts::kDecalsOverlays) {
        SCOPED_TRACE(o.node);
        const facts::DecalsRect r = facts::decals_overlay_rect(o);
        glm::vec2 lo(1e30f), hi(-1e30f);
        for (const glm::vec2 st :
             {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(0, 1), glm::vec2(1, 1)}) {
            const glm::vec4 clip =
                proj * cam->view * glm::vec4(r.origin + st.x * r.edge_u + st.y * r.edge_v, 1.0f);
            ASSERT_GT(clip.w, 0.0f);
            const glm::vec2 ndc = glm::vec2(clip) / clip.w;
            lo = glm::min(lo, ndc);
            hi = glm::max(hi, ndc);
        }
        EXPECT_GE(lo.x, -0.9f);
        EXPECT_GE(lo.y, -0.9f);
        EXPECT_LE(hi.x, 0.9f);
        EXPECT_LE(hi.y, 0.9f);
        const glm::vec3 centre = r.origin + 0.5f * (r.edge_u + r.edge_v);
        const glm::vec3 normal = glm::normalize(glm::cross(r.edge_u, r.edge_v));
        const float facing = glm::dot(normal, glm::normalize(eye - centre));
        EXPECT_GT(facing, 0.34f);  // cos 70 degrees
        const glm::vec2 pixels = (hi - lo) * 0.5f * glm::vec2(320.0f, 180.0f);
        std::printf("%-20s ndc [%.2f %.2f]..[%.2f %.2f], %.0fx%.0f px at 320x180, facing %.2f\n",
                    o.node, lo.x, lo.y, hi.x, hi.y, pixels.x, pixels.y, facing);
        EXPECT_GE(std::min(pixels.x, pixels.y), 16.0f);
    }
}

}  // namespace
}  // namespace ds::scene::builtin
