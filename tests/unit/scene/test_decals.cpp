// Coplanar overlays (decals.h): the classification on hand-made meshes, through the importer
// (draw groups, Scene::decals) and on the built-in scenes.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <set>
#include <string>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "model_builder.h"
#include "renderer/scene/builtin/scene_facts.h"
#include "renderer/scene/decals.h"
#include "renderer/scene/importer.h"
#include "renderer/scene/loader.h"

namespace ds::scene {
namespace {

// Cells [i0, i1) x [j0, j1) of a grid of unit cells in the plane z (facing +Z): vertex (i, j)
// sits at (i, j, z), whichever range it belongs to, so sub-ranges share the exact vertices.
struct Cells {
    int i0 = 0, i1 = 1, j0 = 0, j1 = 1;
};

std::vector<glm::vec3> grid_positions(Cells c, float z, std::vector<uint32_t>& indices) {
    std::vector<glm::vec3> p;
    for (int j = c.j0; j <= c.j1; ++j)
        for (int i = c.i0; i <= c.i1; ++i)
            p.emplace_back(static_cast<float>(i), static_cast<float>(j), z);
    const auto row = static_cast<uint32_t>(c.i1 - c.i0 + 1);
    for (uint32_t j = 0; j + 1 < static_cast<uint32_t>(c.j1 - c.j0 + 1); ++j) {
        for (uint32_t i = 0; i + 1 < row; ++i) {
            const uint32_t a = j * row + i;
            indices.insert(indices.end(), {a, a + 1, a + row + 1, a, a + row + 1, a + row});
        }
    }
    return p;
}

Mesh grid_mesh(Cells c, float z = 0.0f) {
    Mesh m;
    for (const glm::vec3& p : grid_positions(c, z, m.indices)) m.vertices.push_back({p});
    return m;
}

// Bases of `meshes` placed once each by `worlds` (identity when left out).
std::vector<int32_t> bases(const std::vector<Mesh>& meshes, std::vector<glm::mat4> worlds = {}) {
    worlds.resize(meshes.size(), glm::mat4(1.0f));
    std::vector<Instance> instances;
    for (uint32_t i = 0; i < meshes.size(); ++i) instances.push_back({i, worlds[i], ""});
    return find_decal_bases(meshes, instances);
}

using Bases = std::vector<int32_t>;

TEST(Decals, SubsetOfTheBaseCellsLiesOnIt) {
    EXPECT_EQ(bases({grid_mesh({0, 8, 0, 4}), grid_mesh({2, 4, 1, 3})}), (Bases{-1, 0}));
    // Order does not matter: the overlay authored first.
    EXPECT_EQ(bases({grid_mesh({2, 4, 1, 3}), grid_mesh({0, 8, 0, 4})}), (Bases{1, -1}));
}

TEST(Decals, StickingOutOfTheBaseByOneCellIsNot) {
    EXPECT_EQ(bases({grid_mesh({0, 8, 0, 4}), grid_mesh({6, 9, 1, 3})}), (Bases{-1, -1}));
    EXPECT_EQ(bases({grid_mesh({0, 8, 0, 4}), grid_mesh({2, 4, 3, 5})}), (Bases{-1, -1}));
}

TEST(Decals, OverlayAcrossAHoleInTheBaseIsNot) {
    // The wall lacks one triangle of cell (3, 2). The overlay's triangle there has its vertices
    // and edge midpoints on the wall's other triangles: only its inner points see the hole.
    Mesh wall = grid_mesh({0, 8, 0, 4});
    const auto cell = static_cast<std::ptrdiff_t>(2 * 8 + 3);
    wall.indices.erase(wall.indices.begin() + 6 * cell, wall.indices.begin() + 6 * cell + 3);
    EXPECT_EQ(bases({wall, grid_mesh({2, 5, 1, 4})}), (Bases{-1, -1}));
    EXPECT_EQ(bases({wall, grid_mesh({4, 7, 1, 4})}), (Bases{-1, 0}));
}

TEST(Decals, DuplicatesAndPartialOverlapsAreZfightsNotDecals) {
    // The same mesh twice, two meshes with the same vertices, two quads overlapping partly.
    const Mesh wall = grid_mesh({0, 4, 0, 4});
    EXPECT_EQ(bases({wall, wall}), (Bases{-1, -1}));
    std::vector<Instance> twice = {{0, glm::mat4(1.0f), "a"}, {0, glm::mat4(1.0f), "b"}};
    EXPECT_EQ(find_decal_bases({wall}, twice), (Bases{-1, -1}));
    EXPECT_EQ(bases({grid_mesh({0, 4, 0, 4}), grid_mesh({2, 6, 1, 3})}), (Bases{-1, -1}));
    // An overlay on a duplicated wall still lies on it (on the lower index of the equal two).
    EXPECT_EQ(bases({wall, wall, grid_mesh({1, 3, 1, 3})}), (Bases{-1, -1, 0}));
}

TEST(Decals, DifferentDiagonalsOfTheSameSquareAreAZfight) {
    Mesh a = grid_mesh({0, 1, 0, 1});
    Mesh b = a;
    b.indices = {0, 1, 2, 1, 3, 2};  // the other diagonal (vertices (0,0) (1,0) (0,1) (1,1))
    EXPECT_EQ(bases({a, b}), (Bases{-1, -1}));
}

// Offsets along the normal in units of the smallest / largest eps of the overlay's points.
TEST(Decals, ToleranceIsRelativeToTheGeometrysOwnMagnitude) {
    for (const glm::vec3 at : {glm::vec3(0.0f), glm::vec3(900.0f, -2000.0f, 1500.0f)}) {
        SCOPED_TRACE(at.x);
        const glm::mat4 place = glm::translate(glm::mat4(1.0f), at);
        const Cells cells{2, 4, 1, 3};
        const double longest = std::sqrt(2.0);  // a cell's diagonal
        double min_eps = 1e30, max_eps = 0.0;
        for (const Vertex& v : grid_mesh(cells).vertices) {
            const double eps = overlay_epsilon(glm::dvec3(v.position + at), longest);
            min_eps = std::min(min_eps, eps);
            max_eps = std::max(max_eps, eps);
        }
        const Mesh wall = grid_mesh({0, 8, 0, 4});
        EXPECT_EQ(
            bases({wall, grid_mesh(cells, static_cast<float>(0.1 * min_eps))}, {place, place}),
            (Bases{-1, 0}));
        EXPECT_EQ(
            bases({wall, grid_mesh(cells, static_cast<float>(-0.1 * min_eps))}, {place, place}),
            (Bases{-1, 0}));
        EXPECT_EQ(
            bases({wall, grid_mesh(cells, static_cast<float>(100.0 * max_eps))}, {place, place}),
            (Bases{-1, -1}));
    }
}

// zfight's nearly coplanar pairs: 1e-4 of the distance behind, at 1 m and at 5 km.
TEST(Decals, NearlyCoplanarPairsAreNotDecalsAtAnyDistance) {
    for (const float d : {1.0f, 5000.0f}) {
        const float size = 0.2f * d;
        const glm::mat4 front =
            glm::scale(glm::translate(glm::mat4(1.0f), {0, 0, -d}), glm::vec3(size, size, 1.0f));
        const glm::mat4 back =
            glm::scale(glm::translate(glm::mat4(1.0f), {0.1f * size, 0.1f * size, -d - 1e-4f * d}),
                       glm::vec3(0.8f * size, 0.8f * size, 1.0f));
        const Mesh quad = grid_mesh({0, 1, 0, 1});
        EXPECT_EQ(bases({quad, quad}, {front, back}), (Bases{-1, -1})) << d;
        // The same placement without the gap is an overlay: the test above can fail.
        const glm::mat4 on =
            glm::scale(glm::translate(glm::mat4(1.0f), {0.1f * size, 0.1f * size, -d}),
                       glm::vec3(0.8f * size, 0.8f * size, 1.0f));
        EXPECT_EQ(bases({quad, quad}, {front, on}), (Bases{-1, 0})) << d;
    }
}

TEST(Decals, NestedOverlaysBothLieOnTheWall) {
    EXPECT_EQ(bases({grid_mesh({1, 3, 1, 2}), grid_mesh({0, 8, 0, 4}), grid_mesh({0, 5, 0, 3})}),
              (Bases{1, -1, 1}));
}

TEST(Decals, OfSeveralBasesTheLargestWins) {
    // Two walls overlapping partly (a Z-fight: neither lies on the other), both under one
    // overlay; then two bases of equal area: the lower index.
    EXPECT_EQ(bases({grid_mesh({0, 4, 0, 4}), grid_mesh({2, 10, 0, 4}), grid_mesh({2, 4, 1, 3})}),
              (Bases{-1, -1, 1}));
    EXPECT_EQ(bases({grid_mesh({0, 4, 0, 4}), grid_mesh({2, 6, 0, 4}), grid_mesh({2, 4, 1, 3})}),
              (Bases{-1, -1, 0}));
}

TEST(Decals, DegenerateTrianglesAreIgnored) {
    Mesh overlay = grid_mesh({2, 4, 1, 3});
    // A collapsed triangle far off the wall's plane does not stop the overlay lying on it ...
    overlay.vertices.push_back({glm::vec3(3, 2, 5)});
    const auto v = static_cast<uint32_t>(overlay.vertices.size() - 1);
    overlay.indices.insert(overlay.indices.end(), {v, v, v});
    // ... and a mesh of nothing but degenerate triangles is never an overlay.
    Mesh flat;
    flat.vertices = {{glm::vec3(1, 1, 0)}, {glm::vec3(2, 1, 0)}, {glm::vec3(3, 1, 0)}};
    flat.indices = {0, 1, 2, 0, 0, 1};
    EXPECT_EQ(bases({grid_mesh({0, 8, 0, 4}), overlay, flat}), (Bases{-1, 0, -1}));
    EXPECT_EQ(bases({Mesh{}, grid_mesh({0, 8, 0, 4})}), (Bases{-1, -1}));
}

TEST(Decals, OverlayOnTwoFacesLiesOnTheBox) {
    // Two patches on two faces of a box corner, one mesh: every triangle lies on one face.
    Mesh corner = grid_mesh({0, 4, 0, 4});
    Mesh side = grid_mesh({0, 4, 0, 4});
    for (Vertex& v : side.vertices) v.position = {0.0f, v.position.y, v.position.x};
    Mesh strip = grid_mesh({1, 3, 1, 2});
    Mesh strip_side = strip;
    for (Vertex& v : strip_side.vertices) v.position = {0.0f, v.position.y, v.position.x};
    auto join = [](Mesh a, const Mesh& b) {
        const auto offset = static_cast<uint32_t>(a.vertices.size());
        a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
        for (uint32_t i : b.indices) a.indices.push_back(offset + i);
        return a;
    };
    EXPECT_EQ(bases({join(corner, side), join(strip, strip_side)}), (Bases{-1, 0}));
}

// --- through the importer: draw groups and Scene::decals ---

int add_grid(test::ModelBuilder& b, Cells c, int material, float z = 0.0f) {
    std::vector<uint32_t> indices;
    const std::vector<glm::vec3> p = grid_positions(c, z, indices);
    tinygltf::Primitive prim;
    prim.attributes["POSITION"] = b.add_vec3(p);
    prim.attributes["NORMAL"] = b.add_vec3(std::vector<glm::vec3>(p.size(), {0, 0, 1}));
    prim.indices = b.add_indices(indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
    prim.material = material;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    return b.add_mesh({prim});
}

// A node named `name` with `mesh`, placed by one fixed non-trivial TRS.
void add_placed(test::ModelBuilder& b, int mesh, const std::string& name) {
    tinygltf::Node& node = b.model.nodes[static_cast<size_t>(b.add_node(mesh))];
    node.name = name;
    node.translation = {3.25, -1.5, 7.0};
    node.rotation = {0.2126, 0.4252, -0.1063,
                     0.8729};  // a little off unit: the importer normalises
    node.scale = {1.5, 0.75, 2.0};
}

TEST(DecalsImport, OverlayOfTheBaseCellsIsADecalGroup) {
    test::ModelBuilder b;
    const int grey = b.add_material();
    const int poster = b.add_material("BLEND");
    b.add_node(add_grid(b, {0, 8, 0, 4}, grey));
    b.add_node(add_grid(b, {2, 4, 1, 3}, poster));
    const Scene s = import_model(b.model, "t", "mem:t");
    ASSERT_EQ(s.draw_groups.size(), 2u);
    EXPECT_FALSE(s.draw_groups[0].decal);
    EXPECT_TRUE(s.draw_groups[1].decal);
    ASSERT_EQ(s.decals.size(), 1u);
    EXPECT_EQ(s.decals[0].instance, 1u);
    EXPECT_EQ(s.decals[0].base, 0u);
}

TEST(DecalsImport, TheSameNodeTransformKeepsTheOverlayBitIdentical) {
    test::ModelBuilder b;
    const int grey = b.add_material();
    add_placed(b, add_grid(b, {0, 8, 0, 4}, grey), "wall");
    add_placed(b, add_grid(b, {2, 4, 1, 3}, b.add_material("MASK")), "mask");
    add_placed(b, add_grid(b, {5, 7, 1, 3}, b.add_material("BLEND")), "blend");
    const Scene s = import_model(b.model, "t", "mem:t");
    ASSERT_EQ(s.decals.size(), 2u);
    for (const Decal& d : s.decals) EXPECT_EQ(s.instances[d.base].node, "wall");
    EXPECT_EQ(s.instances[s.decals[0].instance].node, "mask");
    EXPECT_EQ(s.instances[s.decals[1].instance].node, "blend");
    EXPECT_NE(s.instances[0].world, glm::mat4(1.0f));
}

TEST(DecalsImport, OneMeshAsOverlayAndElsewhereMakesTwoGroups) {
    test::ModelBuilder b;
    const int grey = b.add_material();
    const int poster = add_grid(b, {2, 4, 1, 3}, b.add_material("BLEND"));
    b.add_node(poster, {0, 0, 2});                // in front of the wall: not coplanar
    b.add_node(add_grid(b, {0, 8, 0, 4}, grey));  // the wall
    b.add_node(poster);                           // on it
    b.add_node(poster, {0, 0, 3});
    const Scene s = import_model(b.model, "t", "mem:t");
    ASSERT_EQ(s.draw_groups.size(), 3u);  // first-use order: poster, wall, poster on the wall
    EXPECT_EQ(s.draw_groups[0].mesh, 0u);
    EXPECT_FALSE(s.draw_groups[0].decal);
    EXPECT_EQ(s.draw_groups[0].instance_count, 2u);
    EXPECT_FALSE(s.draw_groups[1].decal);
    EXPECT_EQ(s.draw_groups[2].mesh, 0u);
    EXPECT_TRUE(s.draw_groups[2].decal);
    EXPECT_EQ(s.draw_groups[2].first_instance, 3u);
    ASSERT_EQ(s.decals.size(), 1u);
    EXPECT_EQ(s.decals[0].instance, 3u);  // final indices, after grouping
    EXPECT_EQ(s.decals[0].base, 2u);
    EXPECT_EQ(s.instances[3].world, glm::mat4(1.0f));
    EXPECT_EQ(s.instances[1].world[3].z, 3.0f);
}

// --- the built-in scenes ---

// Each decal's node name with its base's node name.
std::map<std::string, std::string> decal_nodes(const Scene& s) {
    std::map<std::string, std::string> out;
    for (const Decal& d : s.decals)
        out[s.instances.at(d.instance).node] = s.instances.at(d.base).node;
    return out;
}

// Scene::decals is sorted by instance and names exactly the instances of decal groups.
void expect_consistent(const Scene& s) {
    std::set<uint32_t> in_groups;
    for (const DrawGroup& g : s.draw_groups)
        for (uint32_t i = 0; i < g.instance_count && g.decal; ++i)
            in_groups.insert(g.first_instance + i);
    std::set<uint32_t> listed;
    for (const Decal& d : s.decals) listed.insert(d.instance);
    EXPECT_EQ(listed, in_groups);
    EXPECT_TRUE(
        std::is_sorted(s.decals.begin(), s.decals.end(),
                       [](const Decal& a, const Decal& b) { return a.instance < b.instance; }));
    EXPECT_EQ(listed.size(), s.decals.size());
}

TEST(DecalsBuiltin, DecalsSceneHasExactlyItsOverlaysOnTheirBases) {
    const Scene s = load_scene("decals", Settings{});
    std::map<std::string, std::string> want;
    for (const auto& o : builtin::facts::kDecalsOverlays)
        want[o.node] = builtin::facts::kDecalsSurfaces[o.surface].node;
    EXPECT_EQ(decal_nodes(s), want);
    expect_consistent(s);
}

TEST(DecalsBuiltin, AtriumsDecalNodesLieOnItsWallsAndFloor) {
    using Clock = std::chrono::steady_clock;
    auto ms_since = [](Clock::time_point t) {
        return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
    };
    const Clock::time_point load = Clock::now();
    const Scene s = load_scene("atrium", Settings{});
    const double load_ms = ms_since(load);
    const Clock::time_point start = Clock::now();
    const std::vector<int32_t> again = find_decal_bases(s.meshes, s.instances);
    std::printf("atrium: %zu instances, %llu triangles: loaded in %.1f ms, classified in %.1f ms\n",
                s.instances.size(), static_cast<unsigned long long>(s.triangle_count()), load_ms,
                ms_since(start));
    const auto found = decal_nodes(s);
    size_t decal_named = 0;
    for (const Instance& i : s.instances) decal_named += i.node.starts_with("decal_") ? 1 : 0;
    EXPECT_EQ(decal_named, 15u);
    EXPECT_EQ(found.size(), 15u);
    const std::set<std::string> surfaces = {"far_wall", "near_wall", "left_wall", "right_wall",
                                            "floor"};
    for (const auto& [node, base] : found) {
        EXPECT_TRUE(node.starts_with("decal_")) << node;
        EXPECT_TRUE(surfaces.count(base)) << node << " on " << base;
    }
    EXPECT_EQ(found.at("decal_poster_far_left"), "far_wall");
    EXPECT_EQ(found.at("decal_poster_right_1"), "right_wall");
    EXPECT_EQ(found.at("decal_stain_4"), "floor");
    EXPECT_EQ(std::count_if(again.begin(), again.end(), [](int32_t b) { return b >= 0; }), 15);
    expect_consistent(s);
}

TEST(DecalsBuiltin, ScenesWithoutOverlaysHaveNone) {
    for (const char* name : {"zfight", "overdraw", "foliage", "edges"}) {
        const Scene s = load_scene(name, Settings{});
        EXPECT_TRUE(s.decals.empty()) << name << ": " << decal_nodes(s).begin()->first;
        for (const DrawGroup& g : s.draw_groups) EXPECT_FALSE(g.decal) << name;
    }
    Settings many;
    many.set("zfight_pairs", "16");
    EXPECT_TRUE(load_scene("zfight", many).decals.empty());
}

// Rooms of a wall, two overlays on it, one in front of it and two bumpy props, all under one
// rotated placement per room, on a bumpy terrain whose bounds hold everything.
TEST(DecalsScale, TwoHundredThousandTriangles) {
    std::vector<Mesh> meshes = {grid_mesh({0, 40, 0, 20}), grid_mesh({3, 8, 3, 8}),
                                grid_mesh({20, 25, 10, 15}), grid_mesh({0, 10, 0, 10}),
                                grid_mesh({0, 150, 0, 150})};
    for (Vertex& v : meshes[3].vertices)
        v.position.z = std::sin(v.position.x) * std::cos(v.position.y);
    for (Vertex& v : meshes[4].vertices)
        v.position = {4.0f * v.position.x,
                      30.0f * std::sin(0.3f * v.position.x + 0.2f * v.position.y),
                      4.0f * v.position.y};
    std::vector<Instance> instances = {{4, glm::mat4(1.0f), "terrain"}};
    for (int r = 0; r < 100; ++r) {
        const glm::mat4 room =
            glm::rotate(glm::translate(glm::mat4(1.0f), {6.0f * static_cast<float>(r % 10) * 10.0f,
                                                         0.0f, 60.0f * static_cast<float>(r / 10)}),
                        0.37f * static_cast<float>(r), glm::vec3(0, 1, 0));
        const std::string tag = std::to_string(r);
        instances.push_back({0, room, "wall_" + tag});
        instances.push_back({1, room, "overlay_a_" + tag});
        instances.push_back({2, room, "overlay_b_" + tag});
        instances.push_back({1, glm::translate(room, {0, 0, 0.5f}), "floating_" + tag});
        instances.push_back({3, glm::translate(room, {5, 2, 3}), "prop_a_" + tag});
        instances.push_back({3, glm::translate(room, {15, 2, -3}), "prop_b_" + tag});
    }
    Scene s;
    s.meshes = meshes;
    s.instances = instances;
    ASSERT_GE(s.triangle_count(), 200000u);
    const auto start = std::chrono::steady_clock::now();
    const std::vector<int32_t> base = find_decal_bases(meshes, instances);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf("synthetic: %zu instances, %llu triangles: classified in %.1f ms\n",
                instances.size(), static_cast<unsigned long long>(s.triangle_count()), ms);
    for (size_t i = 0; i < instances.size(); ++i) {
        const std::string& node = instances[i].node;
        if (node.starts_with("overlay_")) {
            ASSERT_GE(base[i], 0) << node;
            EXPECT_EQ(instances[static_cast<size_t>(base[i])].node, "wall_" + node.substr(10))
                << node;
        } else {
            EXPECT_EQ(base[i], -1) << node;
        }
    }
    EXPECT_LT(ms, 5000.0);  // a guard against quadratic behaviour, not a benchmark
}

}  // namespace
}  // namespace ds::scene
