// Alpha coverage across mips (alpha_mip_coverage, alpha_level0, alpha_mip) on foliage through
// the Renderer facade, validation on: the cutoff and the mode switched between frames of one
// renderer (images made, bound and retired without a validation message; the report's
// preserved chain follows the cutoff), and the prepass's alpha_mip image against the frame's
// own surface ids (a level >= 0 exactly where a MASK surface won, -1 elsewhere).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "renderer/frame/alpha_coverage_report.h"
#include "renderer/passes/depth_prepass.h"
#include "renderer/renderer.h"
#include "renderer/vk/capabilities.h"
#include "tests/gpu/passes/shared_renderer.h"

namespace {

using namespace ds;

constexpr uint32_t kWidth = 320, kHeight = 180;

class AlphaMips : public test::SharedScene {
  protected:
    static void SetUpTestSuite() { set_up_with("foliage"); }

    static FrameResult render(const std::vector<std::string>& assignments,
                              std::vector<InspectRequest> inspect = {}) {
        renderer_->camera_cut();  // the image depends on these settings only
        return renderer_->render(scene_->camera, test::settings_of(assignments),
                                 {.width = kWidth,
                                  .height = kHeight,
                                  .read_back = ReadBack::Yes,
                                  .inspect = std::move(inspect)});
    }
};

const scene::MaterialAlphaCoverage& entry(const FrameResult& f, const std::string& material) {
    const AlphaCoverageResult* r = f.find<AlphaCoverageResult>();
    EXPECT_NE(r, nullptr);
    static const scene::MaterialAlphaCoverage none;
    if (!r) return none;
    for (const scene::MaterialAlphaCoverage& m : r->materials)
        if (m.material_name == material) return m;
    ADD_FAILURE() << "no alpha_coverage entry for " << material;
    return none;
}

// The largest |relative - 1| among the levels of at least `size` x `size`.
double worst_off(const std::vector<scene::LevelCoverage>& levels, uint32_t size = 16) {
    double worst = 0.0;
    for (const scene::LevelCoverage& l : levels)
        if (l.width >= size && l.height >= size)
            worst = std::max(worst, std::abs(l.relative - 1.0));
    return worst;
}

void print(const char* what, const scene::MaterialAlphaCoverage& m) {
    std::printf("%s %s cutoff %.2f %s:", what, m.material_name.c_str(), double(m.cutoff),
                scene::to_string(m.mode));
    const auto& levels = m.uploaded.empty() ? m.box : m.uploaded;
    for (const scene::LevelCoverage& l : levels)
        std::printf(" %ux%u %.3f", l.width, l.height, l.coverage);
    std::printf("\n");
}

// Box, preserve, preserve at other cutoffs (global, then per material), box again: each frame
// reports the chain it sampled, and the last one draws what the first drew.
TEST_F(AlphaMips, SwitchingCutoffAndModeBetweenFramesFollowsTheCutoff) {
    const FrameResult box = render({});
    const scene::MaterialAlphaCoverage& b = entry(box, "grass");
    EXPECT_EQ(b.mode, scene::AlphaMipMode::Box);
    EXPECT_TRUE(b.uploaded.empty());
    EXPECT_GT(worst_off(b.box), 0.2) << "foliage's grass thins down the box chain";

    const FrameResult kept = render({"alpha_mip_coverage=preserve"});
    const scene::MaterialAlphaCoverage& k = entry(kept, "grass");
    print("frame 2", k);
    EXPECT_FLOAT_EQ(k.cutoff, 0.5f);
    ASSERT_EQ(k.uploaded.size(), k.box.size());
    EXPECT_LT(worst_off(k.uploaded), 0.02);
    EXPECT_NE(kept.rgba8, box.rgba8) << "the distant grass is drawn fuller";

    for (const std::vector<std::string>& cut :
         {std::vector<std::string>{"alpha_mip_coverage=preserve", "alpha_cutoff=0.3"},
          {"alpha_mip_coverage=preserve", "alpha_cutoff=0.3", "material_alpha_cutoff=grass=0.7"}}) {
        const float expected = cut.size() == 3 ? 0.7f : 0.3f;
        const FrameResult f = render(cut);
        const scene::MaterialAlphaCoverage& g = entry(f, "grass");
        print("then", g);
        EXPECT_FLOAT_EQ(g.cutoff, expected);
        EXPECT_FLOAT_EQ(entry(f, "alpha_ramp").cutoff, 0.3f);
        ASSERT_FALSE(g.uploaded.empty());
        // Level 0 as the new cutoff passes it, the levels kept within 2 % of it from 16x16
        // up (where a scale alone moves several texels at once, the fix-up moves single ones).
        EXPECT_DOUBLE_EQ(g.uploaded[0].coverage, g.box[0].coverage);
        EXPECT_NE(g.uploaded[0].coverage, k.uploaded[0].coverage);
        EXPECT_LT(worst_off(g.uploaded, 16), 0.02);
    }
    const FrameResult again = render({});
    EXPECT_TRUE(entry(again, "grass").uploaded.empty());
    EXPECT_EQ(again.rgba8, box.rgba8) << "box binds the scene's own images again";
}

// surface_id's instance -> whether its material is MASK.
bool masked_at(const scene::Scene& scene, const Renderer& r, float id) {
    const std::optional<SurfaceInfo> s = r.describe_surface(uint32_t(id));
    return s && scene.instance_material(s->instance).alpha_mode == scene::AlphaMode::Mask;
}

// At msaa 1 the winner of each pixel wrote both images: a level where it is MASK, -1 elsewhere.
TEST_F(AlphaMips, AlphaMipHoldsTheSampledLevelOnMaskedPixelsAndNoneElsewhere) {
    for (const char* mode : {"prepass_mode=gbuffer", "prepass_mode=depth"}) {
        SCOPED_TRACE(mode);
        const FrameResult f =
            render({mode, "alpha_mip=on", "surface_id=on"}, {{"alpha_mip"}, {"surface_id"}});
        const InspectedImage* mip = f.image("alpha_mip");
        const InspectedImage* ids = f.image("surface_id");
        ASSERT_TRUE(mip && ids);
        EXPECT_EQ(mip->semantic, graph::Semantic::Scalar);
        EXPECT_EQ(mip->display.palette, graph::Palette::Heat);
        size_t masked = 0, wrong = 0;
        float highest = -1.0f;
        for (size_t i = 0; i < size_t(kWidth) * kHeight; ++i) {
            const float level = mip->texels[i * 4];
            const bool mask = masked_at(*scene_, *renderer_, ids->texels[i * 4]);
            masked += mask;
            wrong += mask ? !(level >= 0.0f) : level != passes::DepthPrepass::kAlphaMipNone;
            highest = std::max(highest, level);
        }
        std::printf("%s: %zu masked pixels, highest level %.2f\n", mode, masked, double(highest));
        EXPECT_GT(masked, 1000u);
        EXPECT_EQ(wrong, 0u);
        EXPECT_GT(highest, 2.0f) << "the far grass samples a small level";
    }
}

// alpha_level0: the test samples level 0, which alpha_mip shows; at msaa 4 (alpha to coverage
// too) the samples are averaged: between -1 and the levels.
TEST_F(AlphaMips, AlphaLevel0AndMultisampledAlphaMipAreValidationClean) {
    const FrameResult zero = render({"alpha_level0=on", "alpha_mip=on"}, {{"alpha_mip"}});
    ASSERT_TRUE(zero.image("alpha_mip"));
    for (size_t i = 0; i < size_t(kWidth) * kHeight; ++i) {
        const float level = zero.image("alpha_mip")->texels[i * 4];
        ASSERT_TRUE(level == 0.0f || level == passes::DepthPrepass::kAlphaMipNone) << level;
    }
    EXPECT_NE(zero.rgba8, render({}).rgba8) << "level 0 keeps the distant blades";
    for (const char* prepass : {"prepass=on", "prepass=off"})
        render({"alpha_level0=on", prepass, "depth_compare=greater_or_equal"});

    const vk::DeviceReport& device = renderer_->device_report();
    if (device.color_sample_counts & device.depth_sample_counts & VK_SAMPLE_COUNT_4_BIT) {
        const FrameResult msaa =
            render({"msaa=4", "alpha_to_coverage=on", "alpha_mip=on"}, {{"alpha_mip"}});
        const InspectedImage* mip = msaa.image("alpha_mip");
        ASSERT_TRUE(mip);
        size_t some = 0;
        for (size_t i = 0; i < size_t(kWidth) * kHeight; ++i) {
            EXPECT_GE(mip->texels[i * 4], -1.0f);
            some += mip->texels[i * 4] >= 0.0f;
        }
        EXPECT_GT(some, 1000u);
    }
    // Not on the subpass path (one more attachment its render pass lacks); with the prepass off
    // the prepass and its image are skipped.
    const FrameResult tiled = render({"render_path=subpass", "alpha_mip=on"});
    EXPECT_NE(
        std::find(tiled.subpass_turned_off.begin(), tiled.subpass_turned_off.end(), "alpha_mip"),
        tiled.subpass_turned_off.end());
    for (const FrameResult& f : {tiled, render({"prepass=off", "alpha_mip=on"})})
        for (const ResourceSummary& r : f.resources) EXPECT_NE(r.name, "alpha_mip");
}

}  // namespace
