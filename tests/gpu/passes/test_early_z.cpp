// Early-Z per pipeline (issue 11 part 3) through the Renderer facade with validation on: every
// geometry pass of the atrium's frame names the pipelines it drew with, each with the verdict
// read from the SPIR-V it was built from, and its draws add up to what the scene's draw groups
// say the pass must have drawn.
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "renderer/passes/draw_counts.h"
#include "renderer/renderer.h"
#include "renderer/vk/capabilities.h"
#include "tests/gpu/passes/shared_renderer.h"

namespace {

using namespace ds;
using scene::AlphaMode;

constexpr uint32_t kEarlyZWidth = 160, kEarlyZHeight = 90;

class EarlyZ : public test::SharedScene {
  protected:
    static void SetUpTestSuite() { set_up_with("atrium"); }

    static FrameResult render(const std::vector<std::string>& assignments) {
        return renderer_->render(
            scene_->camera, test::settings_of(assignments),
            {.width = kEarlyZWidth, .height = kEarlyZHeight, .read_back = ReadBack::No});
    }
    static bool has_msaa4() {
        const vk::DeviceReport& r = renderer_->device_report();
        return (r.color_sample_counts & r.depth_sample_counts & VK_SAMPLE_COUNT_4_BIT) != 0;
    }
    // What the scene says a pass draws: one draw per selected group, or per instance for the
    // sorted passes (prepass_sort, transparent). decal_pass is on: decal groups are the decals
    // pass's alone.
    static uint32_t expected_draws(std::vector<AlphaMode> modes, bool per_instance,
                                   bool decals_only = false) {
        uint32_t n = 0;
        for (const scene::DrawGroup& g : scene_->draw_groups) {
            if (g.decal != decals_only || g.instance_count == 0) continue;
            for (AlphaMode m : modes)
                if (g.alpha_mode == m) n += per_instance ? g.instance_count : 1;
        }
        return n;
    }
};

const PassResult& pass(const FrameResult& f, const std::string& name) {
    for (const PassResult& p : f.passes)
        if (p.name == name) return p;
    static const PassResult none;
    ADD_FAILURE() << "no pass " << name;
    return none;
}

// name -> verdict, and the draws of each.
std::map<std::string, std::string> verdicts(const PassResult& p) {
    std::map<std::string, std::string> out;
    for (const PipelineReport& r : p.pipelines) out[r.name] = r.early_z;
    return out;
}
uint32_t draws_of(const PassResult& p, const std::string& pipeline) {
    for (const PipelineReport& r : p.pipelines)
        if (r.name == pipeline) return r.draws;
    ADD_FAILURE() << p.name << " has no pipeline " << pipeline;
    return 0;
}
uint32_t total_draws(const PassResult& p) {
    uint32_t n = 0;
    for (const PipelineReport& r : p.pipelines) n += r.draws;
    return n;
}

using Verdicts = std::map<std::string, std::string>;

TEST_F(EarlyZ, DefaultFrameSplitsThePrepassIntoAGuaranteedAndALostPipeline) {
    const FrameResult f = render({});
    const PassResult& prepass = pass(f, "depth_prepass");
    EXPECT_EQ(verdicts(prepass), (Verdicts{{"depth_prepass opaque", "guaranteed"},
                                           {"depth_prepass mask", "lost: discard"}}));
    ASSERT_EQ(prepass.pipelines.size(), 2u);
    EXPECT_EQ(prepass.pipelines[0].name, "depth_prepass opaque");  // opaque first
    // prepass_sort (default on): one draw per instance.
    EXPECT_EQ(draws_of(prepass, "depth_prepass opaque"), expected_draws({AlphaMode::Opaque}, true));
    EXPECT_EQ(draws_of(prepass, "depth_prepass mask"), expected_draws({AlphaMode::Mask}, true));
    EXPECT_GT(draws_of(prepass, "depth_prepass mask"), 0u);

    // Forward with the prepass and EQUAL: one pipeline without discard for opaque and MASK.
    const PassResult& forward = pass(f, "forward");
    EXPECT_EQ(verdicts(forward), (Verdicts{{"forward prepass", "guaranteed"}}));
    EXPECT_EQ(total_draws(forward), expected_draws({AlphaMode::Opaque, AlphaMode::Mask}, false));

    // The shadow map: depth only (no fragment shader) and the alpha-tested one.
    const PassResult& shadow = pass(f, "shadow");
    EXPECT_EQ(verdicts(shadow),
              (Verdicts{{"shadow opaque", "guaranteed"}, {"shadow mask", "lost: discard"}}));
    EXPECT_EQ(draws_of(shadow, "shadow opaque"), expected_draws({AlphaMode::Opaque}, false));
    EXPECT_EQ(draws_of(shadow, "shadow mask"), expected_draws({AlphaMode::Mask}, false));

    // Transparent and decals declare early fragment tests: their discard keeps early-Z.
    const PassResult& transparent = pass(f, "transparent");
    EXPECT_EQ(verdicts(transparent), (Verdicts{{"transparent", "guaranteed"}}));
    EXPECT_EQ(total_draws(transparent), expected_draws({AlphaMode::Blend}, true));
    const PassResult& decals = pass(f, "decals");
    for (const auto& [name, verdict] : verdicts(decals)) EXPECT_EQ(verdict, "guaranteed") << name;
    EXPECT_EQ(decals.pipelines.size(), 3u);
    EXPECT_EQ(total_draws(decals),
              expected_draws({AlphaMode::Opaque, AlphaMode::Mask, AlphaMode::Blend}, false, true));
    EXPECT_GT(total_draws(decals), 0u);

    // Fullscreen and compute passes list none.
    EXPECT_TRUE(pass(f, "tonemap").pipelines.empty());
    EXPECT_TRUE(pass(f, "gtao").pipelines.empty());
}

// The atrium's BLEND surfaces are all overlays: transparent draws them once the decals pass is
// off, one draw per instance, back to front.
TEST_F(EarlyZ, TransparentCountsItsSortedDraws) {
    const FrameResult f = render({"decal_pass=off"});
    uint32_t blend_instances = 0;
    for (const scene::DrawGroup& g : scene_->draw_groups)
        if (g.alpha_mode == AlphaMode::Blend) blend_instances += g.instance_count;
    EXPECT_GT(blend_instances, 0u);
    EXPECT_EQ(draws_of(pass(f, "transparent"), "transparent"), blend_instances);
    for (const PassResult& p : f.passes) EXPECT_NE(p.name, "decals");
}

TEST_F(EarlyZ, UnsplitPrepassLosesEarlyZForEverything) {
    const FrameResult f = render({"masked_split=off"});
    const PassResult& prepass = pass(f, "depth_prepass");
    EXPECT_EQ(verdicts(prepass), (Verdicts{{"depth_prepass unsplit", "lost: discard"}}));
    EXPECT_EQ(total_draws(prepass), expected_draws({AlphaMode::Opaque, AlphaMode::Mask}, true));
    // Without sorting, one draw per group.
    const FrameResult unsorted = render({"masked_split=off", "prepass_sort=off"});
    EXPECT_EQ(total_draws(pass(unsorted, "depth_prepass")),
              expected_draws({AlphaMode::Opaque, AlphaMode::Mask}, false));
}

TEST_F(EarlyZ, ForwardKeepsTheDiscardWhereTheTestDoesNotDoItsWork) {
    const FrameResult off = render({"prepass=off"});
    for (const PassResult& p : off.passes) EXPECT_NE(p.name, "depth_prepass");
    const PassResult& forward = pass(off, "forward");
    EXPECT_EQ(verdicts(forward),
              (Verdicts{{"forward opaque", "guaranteed"}, {"forward mask", "lost: discard"}}));
    EXPECT_EQ(draws_of(forward, "forward mask"), expected_draws({AlphaMode::Mask}, false));
    EXPECT_EQ(draws_of(forward, "forward opaque"), expected_draws({AlphaMode::Opaque}, false));
    // greater_or_equal lets the cut-away parts through: the MASK pipeline keeps its discard.
    const FrameResult ge = render({"depth_compare=greater_or_equal"});
    EXPECT_EQ(verdicts(pass(ge, "forward")), (Verdicts{{"forward prepass", "guaranteed"},
                                                       {"forward prepass mask", "lost: discard"}}));
}

TEST_F(EarlyZ, AlphaToCoverageLosesItWhereItIsEnabled) {
    if (!has_msaa4()) GTEST_SKIP() << "the device has no 4x";
    const FrameResult f = render({"msaa=4", "alpha_to_coverage=on"});
    // The prepass's alpha-tested pipeline trades its discard for coverage; opaque keeps early-Z.
    EXPECT_EQ(verdicts(pass(f, "depth_prepass")),
              (Verdicts{{"depth_prepass opaque", "guaranteed"},
                        {"depth_prepass mask a2c", "lost: alpha to coverage"}}));
    // Forward with EQUAL has no alpha-tested pipeline, so no alpha to coverage.
    EXPECT_EQ(verdicts(pass(f, "forward")), (Verdicts{{"forward prepass", "guaranteed"}}));
    const FrameResult off = render({"msaa=4", "alpha_to_coverage=on", "prepass=off"});
    EXPECT_EQ(verdicts(pass(off, "forward")),
              (Verdicts{{"forward opaque", "guaranteed"},
                        {"forward mask a2c", "lost: alpha to coverage"}}));
}

TEST_F(EarlyZ, CountingVariantsSayWhatTheirAtomicsCost) {
    const FrameResult f = render({"count_fragments=on"});
    // Counting without discard declares early fragment tests; the MASK prepass counts after
    // its discard, so its image atomics must run before the (late) depth test.
    EXPECT_EQ(verdicts(pass(f, "depth_prepass")),
              (Verdicts{{"depth_prepass opaque counting", "guaranteed"},
                        {"depth_prepass mask counting", "lost: discard, storage writes"}}));
    EXPECT_EQ(verdicts(pass(f, "forward")), (Verdicts{{"forward prepass counting", "guaranteed"}}));
    EXPECT_EQ(verdicts(pass(f, "transparent")), (Verdicts{{"transparent counting", "guaranteed"}}));
    for (const auto& [name, verdict] : verdicts(pass(f, "decals")))
        EXPECT_EQ(verdict, "guaranteed") << name;
    const FrameResult discards = render({"count_discards=on"});
    EXPECT_EQ(verdicts(pass(discards, "depth_prepass"))["depth_prepass mask count_discards"],
              "lost: discard, storage writes");
}

}  // namespace
