// Z-fighting diagnostics through the Renderer facade, validation on: surface_id names the
// surface that won the prepass, the zfight pass finds exactly coplanar surfaces and no
// separated ones (nor triangles that only share an edge), and off adds nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "renderer/gpu_scene/gpu_scene.h"
#include "renderer/passes/equal_check.h"
#include "renderer/passes/zfight.h"
#include "renderer/renderer.h"
#include "renderer/scene/loader.h"
#include "tests/gpu/passes/shared_renderer.h"

namespace {

using namespace ds;
using test::names;

constexpr uint32_t kZfightWidth = 320, kZfightHeight = 180;

class Zfight : public test::SceneSwitching {
  protected:
    FrameResult render(const std::string& scene_name, const std::vector<std::string>& settings,
                       const InspectRequest& inspect = {}) {
        return SceneSwitching::render(scene_name, settings, kZfightWidth, kZfightHeight,
                                      ReadBack::Yes, inspect);
    }
};

bool has_resource(const FrameResult& f, const std::string& name) {
    for (const ResourceSummary& r : f.resources)
        if (r.name == name) return true;
    return false;
}

std::string node_index(const std::string& node) {
    return node.substr(node.rfind('_') + 1);
}

TEST_F(Zfight, OffAddsNoPassAndNoImage) {
    const FrameResult f = render("zfight", {});
    EXPECT_FALSE(f.find<ZfightResult>());
    EXPECT_FALSE(has_resource(f, "zfight"));
    EXPECT_FALSE(has_resource(f, "surface_id"));
    for (const std::string& n : names(f)) EXPECT_NE(n, "zfight");
}

// Overdraw's layers lie 1 m and more apart, each quad two triangles sharing a diagonal: no
// fight in any format or direction.
TEST_F(Zfight, SeparatedLayersAndSharedEdgesDoNotFight) {
    for (const char* format : {"depth_format=d32f", "depth_format=d24", "depth_format=d16"}) {
        for (const char* reverse : {"reverse_z=on", "reverse_z=off"}) {
            const FrameResult f = render("overdraw", {"zfight=on", format, reverse});
            ASSERT_TRUE(f.find<ZfightResult>()) << format << " " << reverse;
            EXPECT_EQ(f.find<ZfightResult>()->pixels, 0u) << format << " " << reverse;
            EXPECT_TRUE(f.find<ZfightResult>()->pairs.empty()) << format << " " << reverse;
        }
    }
}

// The front layer wins every pixel of the overdraw scene; its surface is named.
TEST_F(Zfight, SurfaceIdNamesTheSurfaceThatWon) {
    const FrameResult f = render("overdraw", {"surface_id=on"}, {"surface_id", 0});
    ASSERT_TRUE(f.inspected);
    ASSERT_EQ(f.inspected->semantic, graph::Semantic::SurfaceId);
    std::set<std::string> nodes;
    for (size_t i = 0; i < f.inspected->texels.size(); i += 4) {
        const auto info = renderer_->describe_surface(uint32_t(f.inspected->texels[i]));
        ASSERT_TRUE(info) << "every pixel is covered";
        nodes.insert(info->name.node);
        EXPECT_LT(info->triangle, 2u) << "a quad has two triangles";
    }
    EXPECT_EQ(nodes, (std::set<std::string>{"layer_0"}));
    EXPECT_FALSE(renderer_->describe_surface(0));
}

// Exactly coplanar quads (A, and B rolled so its diagonal crosses A's) fight in both
// conventions; every pair found is one of the scene's pairs; the competitor image and the
// pixel count agree.
TEST_F(Zfight, CoplanarPairsFightAndOnlyTheirOwnPartners) {
    for (const char* reverse : {"reverse_z=on", "reverse_z=off"}) {
        const FrameResult f = render("zfight", {"zfight=on", reverse}, {"zfight", 0});
        ASSERT_TRUE(f.find<ZfightResult>());
        std::set<std::string> coplanar;
        for (const ZfightPair& p : f.find<ZfightResult>()->pairs) {
            EXPECT_EQ(node_index(p.a.node), node_index(p.b.node)) << p.a.node << " " << p.b.node;
            EXPECT_GT(p.pixels, 0u);
            EXPECT_LE(p.min_steps, 4u);
            if (p.a.node.starts_with("coplanar")) coplanar.insert(p.a.node + "|" + p.b.node);
        }
        EXPECT_EQ(coplanar.size(), 6u) << reverse << ": each of the six coplanar pairs fights";
        ASSERT_TRUE(f.inspected);
        uint64_t pixels = 0;
        for (size_t i = 0; i < f.inspected->texels.size(); i += 4)
            pixels += f.inspected->texels[i] > 0.0f;
        EXPECT_EQ(pixels, f.find<ZfightResult>()->pixels) << reverse;
        EXPECT_GT(pixels, 0u);
    }
}

// msaa > 1 runs per sample (test_zfight_msaa.cpp).
TEST_F(Zfight, NeedsThePrepass) {
    const FrameResult off = render("zfight", {"zfight=on", "prepass=off"});
    EXPECT_FALSE(off.find<ZfightResult>());
    EXPECT_EQ(off.skipped.back(), "zfight: skipped (prepass off)");
}

// equal_check: with invariance the EQUAL test keeps every visible fragment (no holes);
// without it, holes; coplanar surfaces both pass EQUAL (ties), named by the winner.
TEST_F(Zfight, EqualCheckFindsHolesWithoutInvarianceAndTiesOnCoplanarSurfaces) {
    const FrameResult on = render("atrium", {"equal_check=on"});
    ASSERT_TRUE(on.find<EqualCheckResult>());
    EXPECT_EQ(on.find<EqualCheckResult>()->holes, 0u);
    const FrameResult off = render("atrium", {"equal_check=on", "invariant=off"});
    ASSERT_TRUE(off.find<EqualCheckResult>());
    EXPECT_GT(off.find<EqualCheckResult>()->holes, 1000u);
    ASSERT_FALSE(off.find<EqualCheckResult>()->surfaces.empty());
    EXPECT_GT(off.find<EqualCheckResult>()->surfaces[0].holes, 0u);

    const FrameResult ties = render("zfight", {"equal_check=on"}, {"equal_check", 0});
    ASSERT_TRUE(ties.find<EqualCheckResult>());
    EXPECT_GT(ties.find<EqualCheckResult>()->multiple, 0u);
    ASSERT_FALSE(ties.find<EqualCheckResult>()->surfaces.empty());
    for (const EqualCheckSurface& s : ties.find<EqualCheckResult>()->surfaces)
        EXPECT_TRUE(s.name.node.starts_with("coplanar")) << s.name.node;
    // The image marks exactly the counted pixels: 2 for a tie.
    ASSERT_TRUE(ties.inspected);
    uint64_t marked = 0;
    for (size_t i = 0; i < ties.inspected->texels.size(); i += 4)
        marked += ties.inspected->texels[i] == 2.0f;
    EXPECT_EQ(marked, ties.find<EqualCheckResult>()->multiple);
}

TEST_F(Zfight, EqualCheckIsOffByDefaultAndNeedsEqual) {
    const FrameResult none = render("atrium", {});
    EXPECT_FALSE(none.find<EqualCheckResult>());
    EXPECT_FALSE(has_resource(none, "equal_check"));
    const FrameResult ge = render("atrium", {"equal_check=on", "depth_compare=greater_or_equal"});
    EXPECT_FALSE(ge.find<EqualCheckResult>());
    EXPECT_NE(std::find(ge.skipped.begin(), ge.skipped.end(),
                        "equal_check: skipped (depth_compare is not equal)"),
              ge.skipped.end());
}

// Pairs from records, without a device: distinct pixels per pair of instances, the smallest
// gap, most pixels first, unknown ids skipped.
TEST(ZfightPairs, GroupByInstancePairAndCountPixelsOnce) {
    SurfaceTable table;
    table.mesh_names = {"quad"};
    table.material_names = {"red"};
    table.instances = {{0, 2, 0, 0, "a"}, {2, 2, 0, 0, "b"}, {4, 2, 0, 0, "c"}};
    // ids: a = 1, 2; b = 3, 4; c = 5, 6.
    const std::vector<passes::ZfightRecord> records = {
        {10, 1, 3, 2},  {10, 2, 4, 1}, {11, 3, 1, 0},  // a-b in pixels 10 and 11
        {20, 5, 6, 3},                                 // c against itself
        {21, 1, 99, 0},                                // an unknown surface
    };
    const ZfightResult r = passes::zfight_pairs(records, table);
    ASSERT_EQ(r.pairs.size(), 2u);
    EXPECT_EQ(r.pairs[0].a.node, "a");
    EXPECT_EQ(r.pairs[0].b.node, "b");
    EXPECT_EQ(r.pairs[0].pixels, 2u);
    EXPECT_EQ(r.pairs[0].min_steps, 0u);
    EXPECT_EQ(r.pairs[1].a.node, "c");
    EXPECT_EQ(r.pairs[1].b.node, "c");
    EXPECT_EQ(r.pairs[1].pixels, 1u);
    EXPECT_EQ(r.pairs[1].min_steps, 3u);
}

}  // namespace
