// The atrium's reasons to exist: real overdraw from the default view (depth complexity >= 3,
// authored order not front to back), instanced draw groups and exactly coplanar decals.
#include <algorithm>
#include <cstdio>
#include <map>
#include <set>
#include <tuple>

#include <gtest/gtest.h>

#include "model_view.h"
#include "raster.h"
#include "renderer/scene/builtin/builtin.h"

namespace ds::scene::builtin {
namespace {

const tinygltf::Model& atrium() {
    static const tinygltf::Model m = build("atrium", Settings());
    return m;
}

TEST(Atrium, DefaultViewHasDepthComplexityOfAtLeastThree) {
    const auto cam = test::find_camera(atrium());
    ASSERT_TRUE(cam.has_value());
    const std::vector<test::WorldTriangle> tris = test::world_triangles(atrium());
    const test::Coverage culled = test::rasterise(tris, *cam, {160, 90, true});
    const test::Coverage all = test::rasterise(tris, *cam, {160, 90, false});
    std::printf(
        "atrium default view 160x90: depth complexity %.2f (back faces culled), %.2f "
        "(no culling), %.0f%% of pixels covered\n",
        culled.depth_complexity(), all.depth_complexity(),
        100.0 * static_cast<double>(culled.covered_pixels()) / (160.0 * 90.0));
    EXPECT_GE(culled.depth_complexity(), 3.0);
    EXPECT_GT(culled.covered_pixels(), 160u * 90u / 2);  // a courtyard, not a sky view
}

TEST(Atrium, HasOpaqueMaskedAndBlendedMaterials) {
    std::map<std::string, int> modes;
    for (const tinygltf::Material& m : atrium().materials) ++modes[m.alphaMode];
    EXPECT_GE(modes["OPAQUE"], 5);  // stone, brick, marble, wood, fabric ...
    EXPECT_GE(modes["MASK"], 1);
    EXPECT_GE(modes["BLEND"], 2);
    for (const tinygltf::Material& m : atrium().materials) {
        if (m.alphaMode == "MASK") {
            EXPECT_TRUE(m.doubleSided) << m.name;
        }
    }
}

// Draw groups as seed 000 forms them: instances sharing (mesh, alpha mode, double-sided).
TEST(Atrium, RepeatedPiecesAreInstancedThroughNodes) {
    const tinygltf::Model& m = atrium();
    std::map<std::tuple<int, std::string, bool>, int> groups;
    int mesh_nodes = 0;
    for (const tinygltf::Node& n : m.nodes) {
        if (n.mesh < 0) continue;
        ++mesh_nodes;
        const tinygltf::Material& mat =
            m.materials.at(m.meshes.at(n.mesh).primitives.at(0).material);
        ++groups[{n.mesh, mat.alphaMode, mat.doubleSided}];
    }
    int largest = 0;
    for (const auto& [key, count] : groups) largest = std::max(largest, count);
    std::printf(
        "atrium: %zu meshes, %zu materials, %zu nodes (%d with meshes), %zu draw groups, "
        "%zu textures\n",
        m.meshes.size(), m.materials.size(), m.nodes.size(), mesh_nodes, groups.size(),
        m.textures.size());
    EXPECT_GE(largest, 20);  // columns
    EXPECT_LT(groups.size() * 3, static_cast<size_t>(mesh_nodes));
}

TEST(Atrium, AuthoredOrderIsNotFrontToBack) {
    const tinygltf::Model& m = atrium();
    const auto cam = test::find_camera(m);
    ASSERT_TRUE(cam.has_value());
    const glm::vec3 eye = glm::vec3(glm::inverse(cam->view)[3]);
    const std::vector<glm::mat4> world = test::world_matrices(m);
    std::vector<float> column_distances;
    for (size_t i = 0; i < m.nodes.size(); ++i) {
        if (m.nodes[i].mesh >= 0 && m.meshes[m.nodes[i].mesh].name == "column") {
            column_distances.push_back(glm::length(glm::vec3(world[i][3]) - eye));
        }
    }
    ASSERT_GE(column_distances.size(), 20u);
    EXPECT_FALSE(std::is_sorted(column_distances.begin(), column_distances.end()));
    EXPECT_GT(column_distances.front(), column_distances.back());  // farthest first
}

bool same_vertices(const test::WorldTriangle& a, const test::WorldTriangle& b) {
    for (int k = 0; k < 3; ++k) {
        if (a.p[k] != b.p[k]) return false;  // bit-exact on purpose
    }
    return true;
}

TEST(Atrium, DecalsAreExactlyCoplanarWithTheSurfaceUnderThem) {
    const tinygltf::Model& m = atrium();
    const std::vector<test::WorldTriangle> tris = test::world_triangles(m);
    std::vector<const test::WorldTriangle*> opaque;
    for (const auto& t : tris) {
        if (m.materials.at(t.material).alphaMode == "OPAQUE") opaque.push_back(&t);
    }
    int decal_tris = 0;
    std::set<std::string> surfaces;
    for (const auto& t : tris) {
        if (m.materials.at(t.material).alphaMode != "BLEND") continue;
        ++decal_tris;
        const auto under = std::find_if(opaque.begin(), opaque.end(),
                                        [&](const auto* o) { return same_vertices(*o, t); });
        ASSERT_NE(under, opaque.end()) << "decal " << m.nodes[t.node].name << " floats";
        surfaces.insert(m.meshes.at((*under)->mesh).name);
    }
    EXPECT_GE(decal_tris, 10);
    EXPECT_TRUE(surfaces.count("floor"));
    EXPECT_TRUE(surfaces.count("far_wall"));
    EXPECT_GE(surfaces.size(), 3u);
}

}  // namespace
}  // namespace ds::scene::builtin
