// Surface pairs (surface_pairs.h) of the built-in scenes, and a 2M-triangle city whose time is
// printed (not asserted).
#include <chrono>
#include <cstdio>
#include <map>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/scene/builtin/scene_facts.h"
#include "renderer/scene/loader.h"
#include "renderer/scene/surface_pairs.h"

namespace ds::scene {
namespace {

std::vector<SurfacePair> sp_scene_pairs(const Scene& s, double near_gap_max) {
    return find_surface_pairs(s.meshes, s.materials, s.instances, {near_gap_max});
}

std::string sp_describe(const Scene& s, const SurfacePair& p) {
    char gaps[96];
    std::snprintf(gaps, sizeof gaps, " area %.4g gap %.4g..%.4g (%u triangle pairs)",
                  p.overlap_area, p.min_gap, p.max_gap, p.triangle_pairs);
    return std::string(to_string(p.kind)) + ": " + s.instances[p.a].node + " / " +
           s.instances[p.b].node + gaps;
}

// The slot number of a zfight node ("near_back_3": 3).
std::string sp_slot(const std::string& node) {
    return node.substr(node.rfind('_') + 1);
}

// Two parallel unit quads placed by `front` and `back` (same rotation, scaled squares).
struct SpQuadPair {
    double gap = 0.0;       // between their planes, along the normal
    bool overlaps = false;  // seen along the normal
};

SpQuadPair sp_quad_pair(const Instance& front, const Instance& back) {
    const glm::dmat4 f(front.world), b(back.world);
    const glm::dvec3 u = glm::normalize(glm::dvec3(f[0])), v = glm::normalize(glm::dvec3(f[1]));
    const glm::dvec3 d = glm::dvec3(b[3]) - glm::dvec3(f[3]);
    const double reach = 0.5 * (glm::length(glm::dvec3(f[0])) + glm::length(glm::dvec3(b[0])));
    return {std::abs(glm::dot(d, glm::cross(u, v))),
            std::abs(glm::dot(d, u)) < reach && std::abs(glm::dot(d, v)) < reach};
}

// Slot i holds coplanar_a_i / coplanar_b_i (the same square) and near_front_i / near_back_i,
// the back one pushed along the view ray: their planes' distance is less or more than
// zfight_gap_metres, and where the push is long against the quads (the middle distances)
// the back quad no longer lies behind the front one along the normal: no near pair there.
TEST(SurfacePairsBuiltin, ZfightHasExactlyItsCoplanarAndNearPairs) {
    const Scene s = load_scene("zfight", Settings{});
    std::map<std::string, uint32_t> node;
    for (uint32_t i = 0; i < s.instances.size(); ++i) node[s.instances[i].node] = i;
    size_t slots = 0, overlapping = 0;
    for (const Instance& i : s.instances) slots += i.node.starts_with("coplanar_a_") ? 1 : 0;
    std::map<std::string, SpQuadPair> near_pairs;
    for (size_t i = 0; i < slots; ++i) {
        const std::string slot = std::to_string(i);
        const SpQuadPair q = sp_quad_pair(s.instances[node.at("near_front_" + slot)],
                                          s.instances[node.at("near_back_" + slot)]);
        near_pairs[slot] = q;
        overlapping += q.overlaps ? 1 : 0;
    }
    ASSERT_GT(slots, 1u);
    ASSERT_GT(overlapping, 1u);
    size_t coplanar = 0, near = 0;
    for (const SurfacePair& p : sp_scene_pairs(s, 1000.0)) {
        SCOPED_TRACE(sp_describe(s, p));
        const std::string& a = s.instances[p.a].node;
        const std::string& b = s.instances[p.b].node;
        const std::string slot = sp_slot(a);
        EXPECT_EQ(sp_slot(b), slot);
        const bool is_near = p.kind == PairKind::Near;
        EXPECT_TRUE(is_near || p.kind == PairKind::Coplanar);
        (is_near ? near : coplanar) += 1;
        const std::string first = is_near ? "near_front_" : "coplanar_a_";
        const std::string second = is_near ? "near_back_" : "coplanar_b_";
        EXPECT_EQ((std::set<std::string>{a, b}),
                  (std::set<std::string>{first + slot, second + slot}));
        if (!is_near) continue;
        EXPECT_TRUE(near_pairs[slot].overlaps);
        EXPECT_NEAR(p.min_gap, near_pairs[slot].gap, 1e-5 * near_pairs[slot].gap);
        EXPECT_NEAR(p.max_gap, near_pairs[slot].gap, 1e-5 * near_pairs[slot].gap);
    }
    EXPECT_EQ(coplanar, slots);
    EXPECT_EQ(near, overlapping);
    // Without a near gap: the coplanar pairs alone.
    EXPECT_EQ(sp_scene_pairs(s, 0.0).size(), slots);
}

TEST(SurfacePairsBuiltin, DecalsOverlaysAreCoplanarWithTheirBases) {
    const Scene s = load_scene("decals", Settings{});
    std::map<std::string, std::string> want;
    std::map<std::string, double> area;
    for (const auto& o : builtin::facts::kDecalsOverlays) {
        want[o.node] = builtin::facts::kDecalsSurfaces[o.surface].node;
        area[o.node] = (o.i1 - o.i0) * (o.j1 - o.j0) * double{builtin::facts::kDecalsCell} *
                       builtin::facts::kDecalsCell;
    }
    std::map<std::string, std::string> found;
    for (const SurfacePair& p : sp_scene_pairs(s, 0.0)) {
        SCOPED_TRACE(sp_describe(s, p));
        ASSERT_EQ(p.kind, PairKind::Coplanar);
        std::string overlay = s.instances[p.a].node, base = s.instances[p.b].node;
        if (!overlay.starts_with("decal_")) std::swap(overlay, base);
        found[overlay] = base;
        EXPECT_NEAR(p.overlap_area, area[overlay], 1e-5 * area[overlay]);
    }
    EXPECT_EQ(found, want);
}

// Layer k lies kOverdrawLayerSpacing * k behind layer 0, each covering the nearer ones.
TEST(SurfacePairsBuiltin, OverdrawLayersAreNearPairsWithinTheGap) {
    const Scene s = load_scene("overdraw", Settings{});
    const auto layers = static_cast<int>(s.instances.size());
    ASSERT_GT(layers, 2);
    EXPECT_TRUE(sp_scene_pairs(s, 0.0).empty());
    for (const int apart : {1, 2}) {
        const double spacing = builtin::facts::kOverdrawLayerSpacing;
        const auto pairs = sp_scene_pairs(s, apart * spacing);
        // Layers 1 .. apart apart: (layers - 1) + (layers - 2) + ...
        size_t want = 0;
        for (int k = 1; k <= apart; ++k) want += static_cast<size_t>(layers - k);
        EXPECT_EQ(pairs.size(), want);
        for (const SurfacePair& p : pairs) {
            SCOPED_TRACE(sp_describe(s, p));
            EXPECT_EQ(p.kind, PairKind::Near);
            const int ka = std::stoi(sp_slot(s.instances[p.a].node));
            const int kb = std::stoi(sp_slot(s.instances[p.b].node));
            EXPECT_LE(std::abs(ka - kb), apart);
            EXPECT_NEAR(p.min_gap, std::abs(ka - kb) * spacing, 1e-9);
            EXPECT_NEAR(p.max_gap, p.min_gap, 1e-9);
        }
    }
}

// Besides its 15 decals on their walls and floor, the atrium's parts still share planes where
// they meet inside other solids: the gallery arches' ends with the upper slabs' edges (inside
// the arcade arches and the outer walls), the loggia arches' ends with its floor's, and roofs,
// floors and arches ending in the far wall's plane, facing into it. All are coplanar (the
// lint leaves them out as enclosed); nothing is near within 1 cm.
TEST(SurfacePairsBuiltin, AtriumsDecalsAreCoplanarWithTheirBasesAndNothingIsNear) {
    const Scene s = load_scene("atrium", Settings{});
    const auto start = std::chrono::steady_clock::now();
    const auto pairs = sp_scene_pairs(s, 0.01);
    std::printf("atrium: %zu instances, %llu triangles: %zu pairs in %.1f ms\n", s.instances.size(),
                static_cast<unsigned long long>(s.triangle_count()), pairs.size(),
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count());
    std::map<uint32_t, uint32_t> decal_base;
    for (const Decal& d : s.decals) decal_base[d.instance] = d.base;
    ASSERT_EQ(decal_base.size(), 15u);
    size_t decal_pairs = 0;
    for (const SurfacePair& p : pairs) {
        std::printf("  %s\n", sp_describe(s, p).c_str());
        SCOPED_TRACE(sp_describe(s, p));
        EXPECT_EQ(p.kind, PairKind::Coplanar);
        EXPECT_GT(p.overlap_area, 0.0);
        for (const auto& [overlay, base] : {std::pair(p.a, p.b), std::pair(p.b, p.a)}) {
            if (!decal_base.count(overlay)) continue;
            EXPECT_EQ(decal_base.at(overlay), base);
            ++decal_pairs;
        }
    }
    EXPECT_EQ(decal_pairs, decal_base.size());
}

// --- a 2M-triangle city ---

// n x m cells o + e1 * i + e2 * j, facing cross(e2, e1).
void sp_add_face(Mesh& mesh, int n, int m, glm::vec3 o, glm::vec3 e1, glm::vec3 e2) {
    const auto first = static_cast<uint32_t>(mesh.vertices.size());
    for (int j = 0; j <= m; ++j)
        for (int i = 0; i <= n; ++i)
            mesh.vertices.push_back({o + e1 * static_cast<float>(i) + e2 * static_cast<float>(j)});
    const auto row = static_cast<uint32_t>(n + 1);
    for (uint32_t j = 0; j < static_cast<uint32_t>(m); ++j) {
        for (uint32_t i = 0; i < static_cast<uint32_t>(n); ++i) {
            const uint32_t a = first + j * row + i;
            mesh.indices.insert(mesh.indices.end(),
                                {a, a + row, a + row + 1, a, a + row + 1, a + 1});
        }
    }
}

// The box [0, side]^3, each face n x n cells, facing out.
Mesh sp_box(int n, float side) {
    Mesh box;
    const float c = side / static_cast<float>(n);
    const glm::vec3 x(c, 0, 0), y(0, c, 0), z(0, 0, c), o(0.0f);
    sp_add_face(box, n, n, {0, side, 0}, x, z);  // +Y
    sp_add_face(box, n, n, o, z, x);             // -Y
    sp_add_face(box, n, n, {side, 0, 0}, z, y);  // +X
    sp_add_face(box, n, n, o, y, z);             // -X
    sp_add_face(box, n, n, {0, 0, side}, y, x);  // +Z
    sp_add_face(box, n, n, o, x, y);             // -Z
    return box;
}

glm::mat4 sp_at(float x, float y, float z) {
    return glm::translate(glm::mat4(1.0f), {x, y, z});
}

// 800 tessellated 10 m boxes (2028 triangles) 12 m apart, 5 of them twice and 5 with a copy
// 5 m above (flush sides: coplanar), 20 stacks of 10 tessellated floors (1984 triangles) 3 m
// apart, 5 floors with a copy 1/16 m above (near), and a square of 200 x 200 unit tiles, one
// instance each, side by side (none pairs).
TEST(SurfacePairsScale, TwoMillionTrianglesOfBoxesAndStackedFloors) {
    std::vector<Mesh> meshes = {sp_box(13, 10.0f), Mesh{}, Mesh{}};
    sp_add_face(meshes[1], 32, 31, glm::vec3(0.0f), {1, 0, 0}, {0, 0, 1});
    sp_add_face(meshes[2], 1, 1, glm::vec3(0.0f), {1, 0, 0}, {0, 0, 1});
    std::vector<Instance> instances;
    for (int k = 0; k < 790; ++k)
        instances.push_back({0, sp_at(12.0f * float(k % 40), 0, 12.0f * float(k / 40)), "box"});
    for (int k = 0; k < 5; ++k) instances.push_back({0, instances[k].world, "twin"});
    for (int k = 10; k < 15; ++k)
        instances.push_back({0, glm::translate(instances[k].world, {0, 5, 0}), "raised"});
    for (int f = 0; f < 200; ++f)
        instances.push_back({1,
                             sp_at(40.0f * float(f / 10 % 10), 3.0f * float(f % 10),
                                   300.0f + 40.0f * float(f / 100)),
                             "floor"});
    for (int k = 0; k < 5; ++k)
        instances.push_back(
            {1, glm::translate(instances[800 + k * 10].world, {0, 0.0625f, 0}), "near"});
    for (int k = 0; k < 200 * 200; ++k)
        instances.push_back({2, sp_at(float(k % 200), 0, -1.0f - float(k / 200)), "tile"});
    Scene s;
    s.meshes = meshes;
    s.instances = instances;
    ASSERT_GE(s.triangle_count(), 2000000u);
    const std::vector<Material> materials(1);
    const auto start = std::chrono::steady_clock::now();
    const auto pairs = find_surface_pairs(meshes, materials, instances, {0.1});
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf("city: %zu instances, %llu triangles: %zu pairs in %.1f ms\n", instances.size(),
                static_cast<unsigned long long>(s.triangle_count()), pairs.size(), ms);
    std::map<PairKind, size_t> kinds;
    for (const SurfacePair& p : pairs) {
        SCOPED_TRACE(std::string(to_string(p.kind)) + " " + std::to_string(p.a) + " " +
                     std::to_string(p.b));
        ++kinds[p.kind];
        const std::string& b = instances[p.b].node;
        if (p.kind == PairKind::Duplicate) {
            EXPECT_EQ(b, "twin");
        } else if (p.kind == PairKind::Coplanar) {
            EXPECT_EQ(b, "raised");
            EXPECT_NEAR(p.overlap_area, 4 * 10.0 * 5.0, 1e-6);
        } else {
            EXPECT_EQ(b, "near");
            EXPECT_NEAR(p.min_gap, 0.0625, 1e-9);
        }
    }
    EXPECT_EQ(kinds, (std::map<PairKind, size_t>{
                         {PairKind::Coplanar, 5}, {PairKind::Duplicate, 5}, {PairKind::Near, 5}}));
}

}  // namespace
}  // namespace ds::scene
