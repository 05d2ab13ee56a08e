// Every built-in scene is a valid glTF model with the content its purpose needs.
#include <map>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "model_view.h"
#include "renderer/common/error.h"
#include "renderer/scene/builtin/builtin.h"
#include "renderer/scene/builtin/scene_facts.h"

namespace ds::scene::builtin {
namespace {

using test::read_indices;
using test::read_vec3;

std::set<std::string> alpha_modes(const tinygltf::Model& m) {
    std::set<std::string> modes;
    for (const tinygltf::Material& mat : m.materials) modes.insert(mat.alphaMode);
    return modes;
}

void expect_valid_accessors(const tinygltf::Model& m, const std::string& scene) {
    for (const tinygltf::Mesh& mesh : m.meshes) {
        SCOPED_TRACE(scene + " mesh " + mesh.name);
        ASSERT_FALSE(mesh.primitives.empty());
        for (const tinygltf::Primitive& prim : mesh.primitives) {
            EXPECT_EQ(prim.mode, TINYGLTF_MODE_TRIANGLES);
            ASSERT_TRUE(prim.attributes.count("POSITION"));
            const tinygltf::Accessor& pos = m.accessors.at(prim.attributes.at("POSITION"));
            for (const auto& [name, acc] : prim.attributes) {
                EXPECT_EQ(m.accessors.at(acc).count, pos.count) << name;
            }
            const std::vector<glm::vec3> p = read_vec3(m, prim.attributes.at("POSITION"));
            glm::vec3 lo(1e30f), hi(-1e30f);
            for (const glm::vec3& v : p) {
                lo = glm::min(lo, v);
                hi = glm::max(hi, v);
            }
            ASSERT_EQ(pos.minValues.size(), 3u);
            ASSERT_EQ(pos.maxValues.size(), 3u);
            for (int k = 0; k < 3; ++k) {
                EXPECT_EQ(static_cast<float>(pos.minValues[k]), lo[k]);
                EXPECT_EQ(static_cast<float>(pos.maxValues[k]), hi[k]);
            }
            const std::vector<uint32_t> idx = read_indices(m, prim.indices);
            ASSERT_FALSE(idx.empty());
            EXPECT_EQ(idx.size() % 3, 0u);
            for (uint32_t i : idx) ASSERT_LT(i, pos.count);
            ASSERT_GE(prim.material, 0);
            ASSERT_LT(prim.material, static_cast<int>(m.materials.size()));
        }
    }
}

void expect_valid_textures(const tinygltf::Model& m) {
    for (const tinygltf::Texture& t : m.textures) {
        ASSERT_GE(t.source, 0);
        const tinygltf::Image& img = m.images.at(static_cast<size_t>(t.source));
        EXPECT_EQ(img.component, 4);
        EXPECT_EQ(img.bits, 8);
        EXPECT_GE(img.width, 64);
        EXPECT_LE(img.width, 256);
        EXPECT_EQ(img.image.size(), static_cast<size_t>(img.width * img.height * 4));
        EXPECT_FALSE(img.uri.empty());
    }
}

TEST(BuiltinScenes, ListIsInOrderWithAtriumFirst) {
    std::vector<std::string> names;
    for (const Info& i : list()) {
        names.push_back(i.name);
        EXPECT_FALSE(i.description.empty());
        EXPECT_TRUE(exists(i.name));
    }
    EXPECT_EQ(names, (std::vector<std::string>{"atrium", "overdraw", "zfight", "foliage", "edges",
                                               "decals"}));
    EXPECT_FALSE(exists("sponza"));
}

TEST(BuiltinScenes, UnknownNameIsAUsageErrorListingTheValidNames) {
    try {
        build("sponza", Settings());
        FAIL() << "no exception";
    } catch (const UsageError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("sponza"), std::string::npos);
        for (const Info& i : list()) EXPECT_NE(what.find(i.name), std::string::npos) << what;
    }
}

TEST(BuiltinScenes, EverySceneIsValidAndHasACamera) {
    for (const Info& info : list()) {
        SCOPED_TRACE(info.name);
        const tinygltf::Model m = build(info.name, Settings());
        EXPECT_EQ(m.asset.version, "2.0");
        ASSERT_EQ(m.scenes.size(), 1u);
        EXPECT_EQ(m.defaultScene, 0);
        ASSERT_FALSE(m.meshes.empty());
        expect_valid_accessors(m, info.name);
        expect_valid_textures(m);
        const auto cam = test::find_camera(m);
        ASSERT_TRUE(cam.has_value());
        EXPECT_GT(cam->znear, 0.0f);
        EXPECT_GT(cam->zfar, cam->znear);
        for (const tinygltf::BufferView& v : m.bufferViews) {
            EXPECT_LE(v.byteOffset + v.byteLength, m.buffers.at(v.buffer).data.size());
        }
    }
}

TEST(BuiltinScenes, BuildIsDeterministic) {
    for (const Info& info : list()) {
        const tinygltf::Model a = build(info.name, Settings());
        const tinygltf::Model b = build(info.name, Settings());
        EXPECT_EQ(a.buffers.at(0).data, b.buffers.at(0).data) << info.name;
        ASSERT_EQ(a.images.size(), b.images.size());
        for (size_t i = 0; i < a.images.size(); ++i)
            EXPECT_EQ(a.images[i].image, b.images[i].image);
    }
}

TEST(BuiltinScenes, AlphaModesMatchEachScenesPurpose) {
    const Settings s;
    EXPECT_EQ(alpha_modes(build("atrium", s)), (std::set<std::string>{"OPAQUE", "MASK", "BLEND"}));
    EXPECT_EQ(alpha_modes(build("overdraw", s)), (std::set<std::string>{"OPAQUE"}));
    EXPECT_EQ(alpha_modes(build("zfight", s)), (std::set<std::string>{"OPAQUE"}));
    EXPECT_EQ(alpha_modes(build("edges", s)), (std::set<std::string>{"OPAQUE"}));
    EXPECT_EQ(alpha_modes(build("decals", s)), (std::set<std::string>{"OPAQUE", "MASK", "BLEND"}));
    const tinygltf::Model foliage = build("foliage", s);
    EXPECT_TRUE(alpha_modes(foliage).count("MASK"));
    for (const tinygltf::Material& mat : foliage.materials) {
        if (mat.alphaMode != "MASK") continue;
        EXPECT_TRUE(mat.doubleSided) << mat.name;
        EXPECT_DOUBLE_EQ(mat.alphaCutoff, 0.5) << mat.name;
        ASSERT_GE(mat.pbrMetallicRoughness.baseColorTexture.index, 0);
    }
}

TEST(BuiltinScenes, FoliageAlphaRampsFromZeroToOneAcross) {
    const tinygltf::Model m = build("foliage", Settings());
    const tinygltf::Material* ramp = nullptr;
    for (const auto& mat : m.materials) ramp = mat.name == "alpha_ramp" ? &mat : ramp;
    ASSERT_NE(ramp, nullptr);
    const auto& tex = m.textures.at(ramp->pbrMetallicRoughness.baseColorTexture.index);
    const tinygltf::Image& img = m.images.at(tex.source);
    const int row = img.height / 2;
    auto alpha = [&](int x) {
        return img.image[(static_cast<size_t>(row) * img.width + x) * 4 + 3];
    };
    EXPECT_LE(alpha(0), 2);
    EXPECT_GE(alpha(img.width - 1), 253);
    for (int x = 1; x < img.width; ++x) EXPECT_GE(alpha(x), alpha(x - 1));
}

int count_nodes_with_mesh(const tinygltf::Model& m) {
    int n = 0;
    for (const tinygltf::Node& node : m.nodes) n += node.mesh >= 0 ? 1 : 0;
    return n;
}

TEST(BuiltinScenes, OverdrawHasExactlyNQuadsBackToFrontAtKnownDepths) {
    for (int n : {3, 8, 12}) {
        SCOPED_TRACE(n);
        Settings s;
        s.set("overdraw_layers", std::to_string(n));
        const tinygltf::Model m = build("overdraw", s);
        ASSERT_EQ(count_nodes_with_mesh(m), n);
        const std::vector<test::WorldTriangle> tris = test::world_triangles(m);
        EXPECT_EQ(tris.size(), static_cast<size_t>(2 * n));
        // Authored farthest first; each quad's plane is the documented depth.
        for (int i = 0; i < n; ++i) {
            const int k = n - 1 - i;  // layer index, 0 = nearest
            for (const glm::vec3& p : tris[2 * i].p) {
                EXPECT_FLOAT_EQ(p.z, -facts::overdraw_layer_depth(k));
            }
        }
        std::set<std::vector<double>> colours;
        for (const auto& mat : m.materials)
            colours.insert(mat.pbrMetallicRoughness.baseColorFactor);
        EXPECT_EQ(colours.size(), static_cast<size_t>(n));
    }
}

TEST(BuiltinScenes, ZfightPairsFollowTheKnob) {
    for (int n : {1, 6, 16}) {
        Settings s;
        s.set("zfight_pairs", std::to_string(n));
        const tinygltf::Model m = build("zfight", s);
        EXPECT_EQ(count_nodes_with_mesh(m), 4 * n);  // coplanar pair + nearly coplanar pair
        const auto cam = test::find_camera(m);
        ASSERT_TRUE(cam.has_value());
        EXPECT_FLOAT_EQ(cam->znear, facts::kZfightZnear);
        EXPECT_FLOAT_EQ(cam->zfar, facts::kZfightZfar);
    }
}

TEST(BuiltinScenes, ZfightCoplanarPairsShareAPlaneAndNearPairsDoNot) {
    const tinygltf::Model m = build("zfight", Settings());
    const std::vector<test::WorldTriangle> tris = test::world_triangles(m);
    ASSERT_EQ(tris.size() % 8, 0u);  // 4 quads x 2 triangles per slot
    for (size_t slot = 0; slot < tris.size() / 8; ++slot) {
        const test::WorldTriangle& a = tris[slot * 8];
        const glm::vec3 n = glm::normalize(glm::cross(a.p[1] - a.p[0], a.p[2] - a.p[0]));
        const float d = glm::length(a.p[0]);
        for (const glm::vec3& p : tris[slot * 8 + 2].p) {  // coplanar B
            EXPECT_NEAR(glm::dot(n, p - a.p[0]), 0.0f, 1e-5f * d);
        }
        // A quad's two triangles hold opposite corners twice: the mean of the six is its centre.
        auto centre = [&](size_t first) {
            glm::vec3 sum(0.0f);
            for (size_t t = first; t < first + 2; ++t)
                for (const glm::vec3& p : tris[t].p) sum += p;
            return sum / 6.0f;
        };
        const glm::vec3 front = centre(slot * 8 + 4), back = centre(slot * 8 + 6);
        EXPECT_NEAR(glm::length(glm::cross(glm::normalize(front), glm::normalize(back))), 0.0f,
                    1e-5f)
            << "behind the front quad's centre, on one view ray";
        const float gap = front.z - back.z;
        EXPECT_NEAR(gap, facts::zfight_gap_metres(-front.z), 1e-3f * gap);
        EXPECT_LT(gap, 0.15f * -front.z) << "nearly coplanar, not stacked";
    }
}

}  // namespace
}  // namespace ds::scene::builtin
