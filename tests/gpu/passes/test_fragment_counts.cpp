// count_fragments=on through the Renderer facade, validation on: shaded fragments counted on
// entry, discarded ones before the discard and rasterized ones by a measurement draw, per
// pass, against what the scenes' geometry implies, against each other where the pipeline
// decides it (late depth test: shaded = rasterized), and against count_discards' counters.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "renderer/passes/depth_prepass.h"
#include "renderer/renderer.h"
#include "renderer/scene/loader.h"
#include "renderer/vk/capabilities.h"
#include "tests/gpu/passes/shared_renderer.h"

namespace {

using namespace ds;

constexpr uint32_t kCountsWidth = 320, kCountsHeight = 180;
constexpr uint64_t kCountsPixels = uint64_t(kCountsWidth) * kCountsHeight;

class FragmentCounts : public test::SceneSwitching {
  protected:
    FrameResult render(const std::string& scene_name, const std::vector<std::string>& settings) {
        return SceneSwitching::render(scene_name, settings, kCountsWidth, kCountsHeight,
                                      ReadBack::No);
    }
    static constexpr const char* kCounting[] = {"shadow", "depth_prepass", "forward", "decals",
                                                "transparent"};
    bool counts_quads() const { return renderer_->device_report().fragment_quad_operations; }
    static const PassResult& pass(const FrameResult& f, const std::string& name) {
        for (const PassResult& p : f.passes)
            if (p.name == name) return p;
        ADD_FAILURE() << "no pass " << name;
        static const PassResult none;
        return none;
    }
};

// N view-filling opaque layers: forward shades every pixel once with the prepass and N times
// without; the prepass shades each pixel once front to back and N times in authored order
// (back to front); nothing is discarded.
TEST_F(FragmentCounts, OverdrawLayersAreShadedAsTheirDepthOrderImplies) {
    const uint64_t n = 8;  // overdraw_layers' default
    const FrameResult on = render("overdraw", {"count_fragments=on"});
    const FrameResult off = render("overdraw", {"count_fragments=on", "prepass=off"});
    const FrameResult authored = render("overdraw", {"count_fragments=on", "prepass_sort=off"});
    EXPECT_EQ(pass(on, "forward").shaded_fragments, kCountsPixels);
    EXPECT_EQ(pass(off, "forward").shaded_fragments, n * kCountsPixels);
    EXPECT_EQ(pass(on, "depth_prepass").shaded_fragments, kCountsPixels);
    EXPECT_EQ(pass(authored, "depth_prepass").shaded_fragments, n * kCountsPixels);
    for (const FrameResult* f : {&on, &off, &authored}) {
        for (const PassResult& p : f->passes) {
            if (p.shaded_fragments) {
                EXPECT_EQ(p.discarded_fragments, 0u) << p.name;
            }
        }
    }
}

// Foliage's masked prepass pipeline: its per-pixel discard counts and count_discards' atomic
// counters are two independent counts of the same fragments; they agree, split or not.
TEST_F(FragmentCounts, PrepassDiscardsAgreeWithCountDiscards) {
    for (const char* split : {"masked_split=on", "masked_split=off"}) {
        const FrameResult f = render("foliage", {"count_fragments=on", "count_discards=on", split});
        ASSERT_TRUE(f.find<DiscardCounts>()) << split;
        const PassResult& prepass = pass(f, "depth_prepass");
        ASSERT_TRUE(prepass.discarded_fragments) << split;
        EXPECT_GT(*prepass.discarded_fragments, 0u) << split;
        EXPECT_EQ(*prepass.discarded_fragments, f.find<DiscardCounts>()->discarded) << split;
        // Every fragment that ran counts as shaded, the discarded ones too.
        EXPECT_GE(*prepass.shaded_fragments, f.find<DiscardCounts>()->invoked) << split;
        // Forward under EQUAL has no discard: the prepass already cut the alpha.
        EXPECT_EQ(pass(f, "forward").discarded_fragments, 0u) << split;
    }
    // Without the prepass forward's MASK pipeline discards the same cut-away parts.
    const FrameResult off = render("foliage", {"count_fragments=on", "prepass=off"});
    EXPECT_GT(pass(off, "forward").discarded_fragments.value_or(0), 0u);
}

// Rasterized fragments are the layers' depth complexity whatever the depth test keeps: N per
// pixel in the prepass (sorted or not) and in forward (prepass on or off).
TEST_F(FragmentCounts, OverdrawRasterizedIsTheDepthComplexity) {
    const uint64_t n = 8;
    for (const auto& settings :
         std::vector<std::vector<std::string>>{{"count_fragments=on"},
                                               {"count_fragments=on", "prepass_sort=off"},
                                               {"count_fragments=on", "prepass=off"}}) {
        const FrameResult f = render("overdraw", settings);
        EXPECT_EQ(pass(f, "forward").rasterized_fragments, n * kCountsPixels) << settings.back();
        if (settings.back() != "prepass=off") {
            EXPECT_EQ(pass(f, "depth_prepass").rasterized_fragments, n * kCountsPixels);
        }
        EXPECT_EQ(pass(f, "transparent").rasterized_fragments, 0u);
    }
}

// What holds between the three counts of every counting pass, on every scene: a fragment is
// shaded only if rasterized, discarded only if shaded; a pipeline whose depth test is late
// (the unsplit prepass: discard in every draw) shades every fragment it rasterizes, so there
// the measurement draw and the shader's own count must agree exactly, at 1x and 4x.
TEST_F(FragmentCounts, CountsNestAndLateDepthShadesAllRasterized) {
    for (const char* scene : {"atrium", "foliage", "decals"}) {
        for (const char* msaa : {"msaa=1", "msaa=4"}) {
            const FrameResult f = render(scene, {"count_fragments=on", msaa});
            for (const char* name : kCounting) {
                const PassResult* p = nullptr;
                for (const PassResult& r : f.passes)
                    if (r.name == name) p = &r;
                if (!p) continue;  // decals: only where the scene has overlays
                ASSERT_TRUE(p->rasterized_fragments && p->shaded_fragments) << scene << name;
                EXPECT_GE(*p->rasterized_fragments, *p->shaded_fragments) << scene << name;
                EXPECT_GE(*p->shaded_fragments, p->discarded_fragments.value_or(0)) << name;
            }
            const FrameResult late =
                render(scene, {"count_fragments=on", "masked_split=off", msaa});
            const PassResult& prepass = pass(late, "depth_prepass");
            EXPECT_EQ(prepass.shaded_fragments, prepass.rasterized_fragments) << scene << msaa;
            EXPECT_GT(prepass.rasterized_fragments.value_or(0), 0u) << scene;
        }
    }
}

// The shadow pass counts too, over its own map: what it rasterizes does not depend on the
// camera's passes (prepass on or off); foliage's cut-outs are discarded there as well.
TEST_F(FragmentCounts, ShadowPassCountsOverItsMap) {
    const FrameResult on = render("foliage", {"count_fragments=on"});
    const FrameResult off = render("foliage", {"count_fragments=on", "prepass=off"});
    const PassResult& shadow = pass(on, "shadow");
    ASSERT_TRUE(shadow.rasterized_fragments);
    EXPECT_GT(*shadow.rasterized_fragments, 0u);
    EXPECT_EQ(shadow.rasterized_fragments, pass(off, "shadow").rasterized_fragments);
    EXPECT_EQ(shadow.shaded_fragments, pass(off, "shadow").shaded_fragments);
    EXPECT_GT(shadow.discarded_fragments.value_or(0), 0u);
    EXPECT_EQ(pass(render("overdraw", {"count_fragments=on"}), "shadow").discarded_fragments, 0u);
    // shadows=off: no shadow pass, so nothing counted for it.
    const FrameResult none = render("foliage", {"count_fragments=on", "shadows=off"});
    for (const PassResult& p : none.passes) EXPECT_NE(p.name, "shadow");
}

// Quads (devices with quad subgroup operations in fragment shaders): every shaded fragment
// lies in a quad that ran, and each quad that ran holds 1 to 4 of them. Forward over the
// overdraw scene with the prepass shades each pixel once: at least W*H/4 quads. Devices
// without say so: no quad count at all.
TEST_F(FragmentCounts, QuadsHoldTheShadedFragments) {
    const FrameResult f = render("atrium", {"count_fragments=on"});
    for (const char* name : kCounting) {
        for (const PassResult& p : f.passes) {
            if (p.name != name) continue;
            if (!counts_quads()) {
                EXPECT_FALSE(p.quads) << name;
                continue;
            }
            ASSERT_TRUE(p.quads) << name;
            EXPECT_GE(4 * *p.quads, *p.shaded_fragments) << name;
            EXPECT_LE(*p.quads, *p.shaded_fragments) << name;
        }
    }
    if (!counts_quads()) GTEST_SKIP() << "no quad subgroup operations in fragment shaders";
    const FrameResult od = render("overdraw", {"count_fragments=on"});
    EXPECT_GE(pass(od, "forward").quads.value_or(0), kCountsPixels / 4);
}

}  // namespace
