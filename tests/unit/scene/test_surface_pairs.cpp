// Surface pairs (surface_pairs.h): coplanar overlaps, duplicates and near-coplanar pairs of
// hand-made quads, and degenerate triangles. Built-in scenes: test_surface_pairs_scenes.cpp.
#include <cstdio>
#include <map>
#include <random>
#include <tuple>

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/scene/surface_pairs.h"
#include "renderer/scene/surface_pairs_detail.h"

namespace ds::scene {
namespace {

// Material 0 is single-sided, 1 double-sided.
const std::vector<Material> kSpMaterials = [] {
    std::vector<Material> m(2);
    m[1].double_sided = true;
    return m;
}();

// The rectangle [x0, x1] x [y0, y1] in the plane z: facing +Z (-Z when `back`), split along
// (x0, y0)-(x1, y1) or, with `other_diagonal`, along (x1, y0)-(x0, y1).
Mesh sp_rect(double x0, double x1, double y0, double y1, double z, bool back = false,
             bool other_diagonal = false) {
    Mesh m;
    for (const glm::dvec3 p : {glm::dvec3(x0, y0, z), glm::dvec3(x1, y0, z), glm::dvec3(x1, y1, z),
                               glm::dvec3(x0, y1, z)})
        m.vertices.push_back({glm::vec3(p)});
    m.indices = other_diagonal ? std::vector<uint32_t>{0, 1, 3, 1, 2, 3}
                               : std::vector<uint32_t>{0, 1, 2, 0, 2, 3};
    if (back)
        for (size_t t = 0; t < m.indices.size(); t += 3)
            std::swap(m.indices[t + 1], m.indices[t + 2]);
    return m;
}

// `meshes`, one instance each (identity unless `worlds` says otherwise).
std::vector<SurfacePair> sp_find(const std::vector<Mesh>& meshes, double near_gap_max = 0.0,
                                 std::vector<glm::mat4> worlds = {}) {
    worlds.resize(meshes.size(), glm::mat4(1.0f));
    std::vector<Instance> instances;
    for (uint32_t i = 0; i < meshes.size(); ++i) instances.push_back({i, worlds[i], ""});
    return find_surface_pairs(meshes, kSpMaterials, instances, {near_gap_max});
}

TEST(SurfacePairs, SameSquareWithDifferentDiagonalsIsCoplanar) {
    const auto pairs = sp_find({sp_rect(0, 2, 0, 2, 0), sp_rect(0, 2, 0, 2, 0, false, true)});
    ASSERT_EQ(pairs.size(), 1u);
    EXPECT_EQ(pairs[0].a, 0u);
    EXPECT_EQ(pairs[0].b, 1u);
    EXPECT_EQ(pairs[0].kind, PairKind::Coplanar);
    EXPECT_NEAR(pairs[0].overlap_area, 4.0, 1e-12);
    EXPECT_EQ(pairs[0].triangle_pairs, 4u);  // each half of one meets each half of the other
    EXPECT_EQ(pairs[0].min_gap, 0.0);
    EXPECT_EQ(pairs[0].max_gap, 0.0);
    EXPECT_EQ(pairs[0].normal, glm::dvec3(0, 0, 1));
    EXPECT_EQ(pairs[0].point.z, 0.0);
}

TEST(SurfacePairs, PartialOverlapIsTheIntersectionsArea) {
    const auto pairs = sp_find({sp_rect(0, 2, 0, 2, 0), sp_rect(1, 3, 0.5, 2.5, 0)});
    ASSERT_EQ(pairs.size(), 1u);
    EXPECT_EQ(pairs[0].kind, PairKind::Coplanar);
    EXPECT_NEAR(pairs[0].overlap_area, 1.0 * 1.5, 1e-12);
    // The largest overlap's point lies inside the intersection.
    EXPECT_GT(pairs[0].point.x, 1.0);
    EXPECT_LT(pairs[0].point.x, 2.0);
    EXPECT_GT(pairs[0].point.y, 0.5);
    EXPECT_LT(pairs[0].point.y, 2.0);
}

TEST(SurfacePairs, OppositeFacingPairsOnlyWithADoubleSidedMaterial) {
    EXPECT_TRUE(sp_find({sp_rect(0, 2, 0, 2, 0), sp_rect(0, 2, 0, 2, 0, true)}).empty());
    for (size_t two_sided = 0; two_sided < 2; ++two_sided) {
        std::vector<Mesh> meshes = {sp_rect(0, 2, 0, 2, 0), sp_rect(0, 2, 0, 2, 0, true)};
        meshes[two_sided].material = 1;
        const auto pairs = sp_find(meshes);
        ASSERT_EQ(pairs.size(), 1u) << two_sided;
        EXPECT_EQ(pairs[0].kind, PairKind::Coplanar);
        EXPECT_NEAR(pairs[0].overlap_area, 4.0, 1e-12);
    }
}

TEST(SurfacePairs, TouchingTilesAndBoxesAreNotPairs) {
    // Tiles meeting at an edge and at a corner, far from the origin too.
    for (const float at : {0.0f, 3000.0f}) {
        const glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(at, -at, at));
        EXPECT_TRUE(sp_find({sp_rect(0, 1, 0, 1, 0), sp_rect(1, 2, 0, 1, 0, false, true),
                             sp_rect(1, 2, 1, 2, 0)},
                            1.0, {m, m, m})
                        .empty())
            << at;
    }
    // A closed box, face by face, and a second box against its +X face (single-sided).
    std::vector<Mesh> faces;
    std::vector<glm::mat4> worlds;
    const glm::mat4 id(1.0f);
    for (const float shift : {0.0f, 2.0f}) {
        const glm::mat4 at = glm::translate(id, {shift, 0, 0});
        for (int axis = 0; axis < 3; ++axis) {
            const glm::vec3 about = axis == 0 ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
            const glm::mat4 turn = axis == 2 ? id : glm::rotate(id, glm::radians(90.0f), about);
            faces.push_back(sp_rect(-1, 1, -1, 1, 1));
            worlds.push_back(at * turn);
            faces.push_back(sp_rect(-1, 1, -1, 1, -1, true));
            worlds.push_back(at * turn);
        }
    }
    EXPECT_TRUE(sp_find(faces, 0.0, worlds).empty());
}

TEST(SurfacePairs, TheSameMeshAtTheSameTransformIsADuplicate) {
    std::vector<Mesh> meshes = {sp_rect(0, 2, 0, 2, 0)};
    const glm::mat4 m = glm::rotate(glm::translate(glm::mat4(1.0f), {5, 6, 7}), 0.3f, {1, 2, 3});
    const std::vector<Instance> instances = {{0, m, "a"}, {0, m, "b"}};
    const auto pairs = find_surface_pairs(meshes, kSpMaterials, instances, {1.0});
    ASSERT_EQ(pairs.size(), 1u);
    EXPECT_EQ(pairs[0].kind, PairKind::Duplicate);
    EXPECT_NEAR(pairs[0].overlap_area, 4.0, 1e-5);
}

TEST(SurfacePairs, ACopiedMeshIsADuplicate) {
    const auto pairs = sp_find({sp_rect(0, 2, 0, 2, 0), sp_rect(0, 2, 0, 2, 0)});
    ASSERT_EQ(pairs.size(), 1u);
    EXPECT_EQ(pairs[0].kind, PairKind::Duplicate);
    // The same square with its vertices in another order is only coplanar.
    Mesh turned = sp_rect(0, 2, 0, 2, 0);
    turned.indices = {1, 2, 0, 2, 3, 0};
    EXPECT_EQ(sp_find({sp_rect(0, 2, 0, 2, 0), turned}).at(0).kind, PairKind::Coplanar);
}

TEST(SurfacePairs, ParallelQuadsAtAGapAreNearUpToTheMaximum) {
    for (const double base : {0.0, 1000.0}) {
        for (const double gap : {0.125, 0.25}) {
            SCOPED_TRACE(base + gap);
            const std::vector<Mesh> meshes = {sp_rect(0, 2, 0, 2, base),
                                              sp_rect(0.5, 1.5, 0.5, 1.5, base + gap)};
            const auto pairs = sp_find(meshes, 0.25);
            ASSERT_EQ(pairs.size(), 1u);
            EXPECT_EQ(pairs[0].kind, PairKind::Near);
            EXPECT_NEAR(pairs[0].min_gap, gap, 1e-9 * gap);
            EXPECT_NEAR(pairs[0].max_gap, gap, 1e-9 * gap);
            EXPECT_NEAR(pairs[0].overlap_area, 1.0, 1e-9);
            EXPECT_TRUE(sp_find(meshes, 0.1).empty());
            EXPECT_TRUE(sp_find(meshes, 0.0).empty());
            // The quad behind: the gap is a distance either way.
            const auto behind = sp_find({meshes[0], sp_rect(0.5, 1.5, 0.5, 1.5, base - gap)}, 0.25);
            ASSERT_EQ(behind.size(), 1u);
            EXPECT_NEAR(behind[0].min_gap, gap, 1e-9 * gap);
        }
    }
}

// b rises from z = 0.1 at x = 0 to 0.12 at x = 2 (0.57 degrees) over a at z = 0.
TEST(SurfacePairs, ATiltedNearPairsGapsRunOverTheOverlap) {
    Mesh tilted = sp_rect(0, 2, 0, 2, 0);
    for (Vertex& v : tilted.vertices) v.position.z = 0.1f + 0.01f * v.position.x;
    const auto pairs = sp_find({sp_rect(0, 2, 0, 2, 0), tilted}, 0.2);
    ASSERT_EQ(pairs.size(), 1u);
    EXPECT_EQ(pairs[0].kind, PairKind::Near);
    EXPECT_NEAR(pairs[0].min_gap, 0.1, 1e-7);
    EXPECT_NEAR(pairs[0].max_gap, 0.12, 1e-7);
    EXPECT_NEAR(pairs[0].overlap_area, 4.0, 1e-9);
    // Planes that cross inside the overlap are neither coplanar nor near.
    for (Vertex& v : tilted.vertices) v.position.z = -0.01f + 0.01f * v.position.x;
    EXPECT_TRUE(sp_find({sp_rect(0, 2, 0, 2, 0), tilted}, 1.0).empty());
    // Beyond the facing angle (0.1 rad) nothing pairs.
    for (Vertex& v : tilted.vertices) v.position.z = 0.1f + 0.1f * v.position.x;
    EXPECT_TRUE(sp_find({sp_rect(0, 2, 0, 2, 0), tilted}, 1.0).empty());
}

// A mirroring transform turns the winding over, and the facing with it.
TEST(SurfacePairs, AMirroredInstanceFacesTheWayItsMirrorImageDoes) {
    const std::vector<Mesh> meshes = {sp_rect(-1, 1, -1, 1, 0)};
    const glm::mat4 mirror = glm::scale(glm::mat4(1.0f), {-1, 1, 1});
    const glm::mat4 turn = glm::rotate(glm::mat4(1.0f), glm::radians(180.0f), {0, 1, 0});
    auto pairs = [&](const glm::mat4& m) {
        return find_surface_pairs(meshes, kSpMaterials, {{0, glm::mat4(1.0f), "a"}, {0, m, "b"}});
    };
    const auto mirrored = pairs(mirror);  // faces +Z: the same square, other corners
    ASSERT_EQ(mirrored.size(), 1u);
    EXPECT_EQ(mirrored[0].kind, PairKind::Coplanar);
    EXPECT_NEAR(mirrored[0].overlap_area, 4.0, 1e-12);
    EXPECT_TRUE(pairs(turn).empty());            // faces -Z
    EXPECT_EQ(pairs(turn * mirror).size(), 0u);  // mirrored, then turned: -Z
    EXPECT_EQ(pairs(mirror * mirror).at(0).kind, PairKind::Duplicate);
}

TEST(SurfacePairs, DegenerateTrianglesNeverPair) {
    Mesh sliver;
    for (const glm::vec3 p : {glm::vec3(0, 0, 0), glm::vec3(1, 1, 0), glm::vec3(2, 2, 0)})
        sliver.vertices.push_back({p});
    sliver.indices = {0, 1, 2, 0, 2, 1};
    EXPECT_TRUE(sp_find({sliver, sliver}).empty());
}

TEST(SurfacePairsDegenerate, ByAreaAndByIndexPerMesh) {
    Mesh m;
    for (const glm::vec3 p : {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0),
                              glm::vec3(2, 2, 2), glm::vec3(3, 3, 3), glm::vec3(0.5f, 1e-3f, 0)})
        m.vertices.push_back({p});
    m.indices = {0, 1, 2,   // valid
                 0, 1, 5,   // thin (1 : 1000) but valid
                 0, 3, 4,   // three distinct collinear corners: zero area
                 1, 1, 2,   // a repeated index
                 0, 1, 2};  // valid
    const Mesh fine = sp_rect(0, 1, 0, 1, 0);
    const auto found = find_degenerate_triangles({fine, m, fine});
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].mesh, 1u);
    EXPECT_EQ(found[0].count, 2u);
    EXPECT_EQ(found[0].first, 2u);
    // Below the threshold by area alone: a corner 1e-8 off the line of a unit edge.
    EXPECT_TRUE(degenerate_triangle({0, 0, 0}, {1, 0, 0}, {0.5, 1e-8, 0}));
    EXPECT_FALSE(degenerate_triangle({0, 0, 0}, {1, 0, 0}, {0.5, 1e-6, 0}));
    EXPECT_TRUE(degenerate_triangle({1, 2, 3}, {1, 2, 3}, {1, 2, 3}));
}

// --- against every triangle pair ---

struct SpTally {
    uint32_t count = 0;
    double area = 0.0, min_gap = 1e300;
};
using SpTallies = std::map<std::tuple<uint32_t, uint32_t, PairKind>, SpTally>;

// The rules applied to every triangle pair of every instance pair: what the broadphase must
// neither lose nor count twice.
SpTallies sp_every_pair(const std::vector<Mesh>& meshes, const std::vector<Instance>& instances,
                        double near_gap_max) {
    std::vector<detail::PairInstance> placed(instances.size());
    for (size_t i = 0; i < instances.size(); ++i) {
        placed[i].mesh = &meshes[instances[i].mesh];
        placed[i].world = glm::dmat4(instances[i].world);
        placed[i].facing = glm::determinant(glm::dmat3(placed[i].world)) < 0.0 ? -1.0 : 1.0;
        placed[i].double_sided = kSpMaterials[placed[i].mesh->material].double_sided;
    }
    SpTallies out;
    detail::WorldTriangle a, b;
    for (uint32_t i = 0; i < placed.size(); ++i) {
        for (uint32_t j = i + 1; j < placed.size(); ++j) {
            for (uint32_t ta = 0; detail::world_triangle(placed[i], ta, a); ++ta) {
                for (uint32_t tb = 0; detail::world_triangle(placed[j], tb, b); ++tb) {
                    const auto c = detail::triangle_contact(
                        a, b, placed[i].double_sided || placed[j].double_sided, near_gap_max);
                    if (c.kind == detail::Contact::None) continue;
                    const auto kind =
                        c.kind == detail::Contact::Near ? PairKind::Near : PairKind::Coplanar;
                    SpTally& t = out[{i, j, kind}];
                    ++t.count;
                    t.area += c.area;
                    t.min_gap = std::min(t.min_gap, c.min_gap);
                }
            }
        }
    }
    return out;
}

// 400 instances of two random triangles on 24 planes: seven directions (axes, one on the fold
// of n and -n, one on a direction bin's edge, one at a bin's corner, 8 degrees off its centre),
// each jittered up to 3 degrees per plane but the first seven, at offsets 0, `offsets[0]` and
// `offsets[1]` along it; either side facing, single- and double-sided, a quarter placed by a
// mirroring node.
struct SpRandomScene {
    std::vector<Mesh> meshes;
    std::vector<Instance> instances;
};

SpRandomScene sp_random_scene(uint32_t seed, std::array<double, 2> offsets) {
    std::mt19937 random(seed);
    auto uniform = [&](double lo, double hi) {
        return std::uniform_real_distribution<double>(lo, hi)(random);
    };
    const glm::dvec3 fold = glm::normalize(glm::dvec3(1, 2, 4));
    const std::vector<glm::dvec3> directions = {
        {1, 0, 0},   {0, 1, 0}, {0, 0, 1},       glm::cross(fold, glm::dvec3(1, 0, 0)),
        {0.1, 0, 1}, {1, 1, 0}, {0.1, 0.1, 0.99}};
    std::vector<glm::dmat3> planes;  // u, v, n
    for (size_t i = 0; i < 24; ++i) {
        const glm::dvec3 jitter(uniform(-0.03, 0.03), uniform(-0.03, 0.03), uniform(-0.03, 0.03));
        const glm::dvec3 n = glm::normalize(directions[i % 7] + (i < 7 ? glm::dvec3(0) : jitter));
        const glm::dvec3 u = glm::normalize(glm::cross(n, glm::dvec3(0.3, 0.5, 0.7)));
        const double offset = i % 3 == 0 ? 0.0 : offsets[i % 3 - 1];
        planes.push_back({u, glm::cross(n, u), n * offset});
    }
    SpRandomScene out;
    const glm::mat4 mirror = glm::scale(glm::mat4(1.0f), {-1, 1, 1});
    for (uint32_t i = 0; i < 400; ++i) {
        const glm::dmat3& p = planes[random() % planes.size()];
        const bool mirrored = random() % 4 == 0;
        Mesh m;
        m.material = random() % 2;
        for (int t = 0; t < 2; ++t) {
            const glm::dvec3 centre = p[2] + p[0] * uniform(-1, 1) + p[1] * uniform(-1, 1);
            for (int k = 0; k < 3; ++k) {
                const glm::dvec3 q = centre + p[0] * uniform(-0.8, 0.8) + p[1] * uniform(-0.8, 0.8);
                m.vertices.push_back({glm::vec3(mirrored ? glm::dvec3(-q.x, q.y, q.z) : q)});
                m.indices.push_back(static_cast<uint32_t>(m.indices.size()));
            }
            if (random() % 2)
                std::swap(m.indices[m.indices.size() - 1], m.indices[m.indices.size() - 2]);
        }
        out.meshes.push_back(m);
        out.instances.push_back({i, mirrored ? mirror : glm::mat4(1.0f), ""});
    }
    return out;
}

TEST(SurfacePairs, FindsWhatEveryTrianglePairGives) {
    struct Case {
        std::array<double, 2> offsets;
        double near_gap_max;
    };
    for (const Case& c : {Case{{0.003, 0.02}, 0.01}, Case{{0.2, 0.5}, 0.6}}) {
        SCOPED_TRACE(c.near_gap_max);
        const SpRandomScene s = sp_random_scene(7, c.offsets);
        const SpTallies want = sp_every_pair(s.meshes, s.instances, c.near_gap_max);
        std::map<PairKind, size_t> kinds;
        for (const auto& [key, tally] : want) ++kinds[std::get<2>(key)];
        std::printf("random planes, near gap %g: %zu coplanar and %zu near pairs\n", c.near_gap_max,
                    kinds[PairKind::Coplanar], kinds[PairKind::Near]);
        EXPECT_GT(kinds[PairKind::Coplanar], 50u);
        EXPECT_GT(kinds[PairKind::Near], 50u);
        const auto found =
            find_surface_pairs(s.meshes, kSpMaterials, s.instances, {c.near_gap_max});
        EXPECT_EQ(found.size(), want.size());
        for (const SurfacePair& p : found) {
            SCOPED_TRACE(std::to_string(p.a) + " " + std::to_string(p.b) + " " + to_string(p.kind));
            const auto it = want.find({p.a, p.b, p.kind});
            ASSERT_NE(it, want.end());
            EXPECT_EQ(p.triangle_pairs, it->second.count);
            EXPECT_NEAR(p.overlap_area, it->second.area, 1e-9);
            if (p.kind == PairKind::Near) {
                EXPECT_EQ(p.min_gap, it->second.min_gap);
            }
        }
    }
}

}  // namespace
}  // namespace ds::scene
