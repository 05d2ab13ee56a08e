// count_fragments=on through the Renderer facade, validation on: shaded fragments counted on
// entry and discarded ones before the discard, per pass, against what the scenes' geometry
// implies, and against count_discards' independent counters.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "renderer/renderer.h"
#include "renderer/scene/loader.h"
#include "tests/unit/passes/shared_renderer.h"

namespace {

using namespace ds;

constexpr uint32_t kWidth = 320, kHeight = 180;
constexpr uint64_t kPixels = uint64_t(kWidth) * kHeight;

class FragmentCounts : public test::SceneSwitching {
  protected:
    FrameResult render(const std::string& scene_name, const std::vector<std::string>& settings) {
        return SceneSwitching::render(scene_name, settings, kWidth, kHeight, ReadBack::No);
    }
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
    EXPECT_EQ(pass(on, "forward").shaded_fragments, kPixels);
    EXPECT_EQ(pass(off, "forward").shaded_fragments, n * kPixels);
    EXPECT_EQ(pass(on, "depth_prepass").shaded_fragments, kPixels);
    EXPECT_EQ(pass(authored, "depth_prepass").shaded_fragments, n * kPixels);
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
        ASSERT_TRUE(f.masked_discards) << split;
        const PassResult& prepass = pass(f, "depth_prepass");
        ASSERT_TRUE(prepass.discarded_fragments) << split;
        EXPECT_GT(*prepass.discarded_fragments, 0u) << split;
        EXPECT_EQ(*prepass.discarded_fragments, f.masked_discards->discarded) << split;
        // Every fragment that ran counts as shaded, the discarded ones too.
        EXPECT_GE(*prepass.shaded_fragments, f.masked_discards->invoked) << split;
        // Forward under EQUAL has no discard: the prepass already cut the alpha.
        EXPECT_EQ(pass(f, "forward").discarded_fragments, 0u) << split;
    }
    // Without the prepass forward's MASK pipeline discards the same cut-away parts.
    const FrameResult off = render("foliage", {"count_fragments=on", "prepass=off"});
    EXPECT_GT(pass(off, "forward").discarded_fragments.value_or(0), 0u);
}

}  // namespace
