// Alpha-tested (MASK) geometry through the Renderer facade with validation on: alpha cutoff
// (global and per material) on the foliage scene, alpha-to-coverage and per-sample shading at
// 4x, and the prepass's discard counters (count_discards=on).
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "renderer/common/error.h"
#include "renderer/passes/depth_prepass.h"
#include "renderer/renderer.h"
#include "renderer/scene/loader.h"
#include "renderer/vk/capabilities.h"
#include "tests/gpu/passes/shared_renderer.h"

namespace {

using namespace ds;

constexpr uint32_t kAlphaWidth = 240, kAlphaHeight = 135;

class Alpha : public test::SharedRenderer {
  protected:
    static void SetUpTestSuite() {
        guarded([] {
            create_renderer();
            foliage_ = new scene::Scene(scene::load_scene("foliage", Settings{}));
            renderer_->set_scene(*foliage_);
        });
    }
    static void TearDownTestSuite() {
        delete foliage_;
        foliage_ = nullptr;
        SharedRenderer::TearDownTestSuite();
    }

    static FrameResult render(const std::vector<std::string>& assignments) {
        return render(foliage_->camera, assignments);
    }
    static FrameResult render(const scene::Camera& camera,
                              const std::vector<std::string>& assignments) {
        return renderer_->render(
            camera, test::settings_of(assignments),
            {.width = kAlphaWidth, .height = kAlphaHeight, .read_back = ReadBack::Yes});
    }
    // After a camera cut: temporal AO forgets the previous frame, so the image depends on
    // these settings only (images are compared across different previous frames).
    static FrameResult render_cut(const std::vector<std::string>& assignments) {
        renderer_->camera_cut();
        return render(assignments);
    }
    static bool has_msaa4() {
        const vk::DeviceReport& r = renderer_->device_report();
        return (r.color_sample_counts & r.depth_sample_counts & VK_SAMPLE_COUNT_4_BIT) != 0;
    }

    static scene::Scene* foliage_;
};

scene::Scene* Alpha::foliage_ = nullptr;

std::string cutoff(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "alpha_cutoff=%.1f", double(value));
    return text;
}

// foliage's MASK materials: the flat ramp cards, the leaf-shaped cards and the grass bushes.
constexpr const char* kRamp = "alpha_ramp";
constexpr const char* kLeaf = "alpha_ramp_leaf";
constexpr const char* kGrass = "grass";

std::string per_material(const std::vector<std::pair<const char*, float>>& cutoffs) {
    std::string text = "material_alpha_cutoff=";
    for (size_t i = 0; i < cutoffs.size(); ++i) {
        char entry[64];
        std::snprintf(entry, sizeof entry, "%s%s=%.1f", i ? "," : "", cutoffs[i].first,
                      double(cutoffs[i].second));
        text += entry;
    }
    return text;
}

// Every card's alpha ramps across it: a higher cutoff cuts more of each card away. From the
// scene's own camera the backdrop and ground fill the frame (covered_pixels counts depth, not
// colour), so this looks up from the ground at the middle ramp card (x 0, z -3, 2 m tall,
// material alpha_ramp) until its upper part stands against the sky above the backdrop: there
// what the cutoff removes is no longer covered.
scene::Camera ramp_card_against_the_sky(const scene::Camera& base) {
    scene::Camera camera = base;
    camera.position = {0.0f, 0.15f, -1.6f};
    camera.forward = glm::normalize(glm::vec3(0.0f, 2.2f, -3.0f) - camera.position);
    camera.up = {0.0f, 1.0f, 0.0f};
    return camera;
}

TEST_F(Alpha, RaisingTheCutoffLowersCoveredPixels) {
    const scene::Camera camera = ramp_card_against_the_sky(foliage_->camera);
    uint64_t previous = UINT64_MAX;
    for (float c = 0.1f; c < 0.95f; c += 0.2f) {
        SCOPED_TRACE(cutoff(c));
        const FrameResult f = render(camera, {cutoff(c)});
        ASSERT_TRUE(f.covered_pixels);
        std::printf("%s: covered %llu\n", cutoff(c).c_str(), (unsigned long long)*f.covered_pixels);
        EXPECT_LT(*f.covered_pixels, previous);
        previous = *f.covered_pixels;
    }
}

// 4x with alpha-to-coverage: the alpha-tested edges of the leaves become partial coverage,
// so more pixels hold samples that are not all equal than when the discard cuts whole pixels.
TEST_F(Alpha, AlphaToCoverageGivesPartialCoverageAlongLeafEdges) {
    if (!has_msaa4()) GTEST_SKIP() << "the device has no 4x";
    for (const char* prepass : {"prepass=on", "prepass=off"}) {
        SCOPED_TRACE(prepass);
        const FrameResult off = render({"msaa=4", prepass, "alpha_to_coverage=off"});
        const FrameResult on = render({"msaa=4", prepass, "alpha_to_coverage=on"});
        ASSERT_TRUE(off.msaa.edge_pixels && on.msaa.edge_pixels);
        std::printf("%s: edge pixels a2c off %llu, on %llu\n", prepass,
                    (unsigned long long)*off.msaa.edge_pixels,
                    (unsigned long long)*on.msaa.edge_pixels);
        EXPECT_GT(double(*on.msaa.edge_pixels), 1.2 * double(*off.msaa.edge_pixels));
    }
}

// At 1x the knob changes nothing (it needs samples to cover).
TEST_F(Alpha, AlphaToCoverageAtOneSampleChangesNothing) {
    const FrameResult off = render({"alpha_to_coverage=off"});
    const FrameResult on = render({"alpha_to_coverage=on"});
    EXPECT_EQ(off.rgba8, on.rgba8);
}

// Per-sample shading: validation-clean at 4x with and without the prepass; with exact counts
// the forward pass shades more fragments (one per covered sample, not per pixel).
TEST_F(Alpha, SampleShadingShadesPerSample) {
    if (!has_msaa4()) GTEST_SKIP() << "the device has no 4x";
    if (!renderer_->device_report().sample_rate_shading) GTEST_SKIP() << "no sampleRateShading";
    for (const char* prepass : {"prepass=on", "prepass=off"}) {
        SCOPED_TRACE(prepass);
        auto forward = [](const FrameResult& f) {
            for (const PassResult& p : f.passes)
                if (p.name == "forward") return p.shaded_fragments.value_or(0);
            return uint64_t(0);
        };
        const FrameResult off = render({"msaa=4", prepass, "count_fragments=on"});
        const FrameResult on =
            render({"msaa=4", prepass, "count_fragments=on", "sample_shading=on"});
        std::printf("%s: forward fragments per-pixel %llu, per-sample %llu\n", prepass,
                    (unsigned long long)forward(off), (unsigned long long)forward(on));
        EXPECT_GT(forward(on), 2 * forward(off));
    }
}

// count_discards: the MASK prepass pipeline's discard makes its depth test late, so every
// rasterized MASK fragment runs the shader whatever the cutoff (invoked stays), and a higher
// cutoff discards more of them. Without the prepass nothing is counted.
TEST_F(Alpha, RaisingTheCutoffRaisesDiscards) {
    const FrameResult plain = render({});
    EXPECT_FALSE(plain.find<DiscardCounts>());
    std::vector<DiscardCounts> counts;
    for (const char* c : {"alpha_cutoff=0.1", "alpha_cutoff=0.5", "alpha_cutoff=0.9"}) {
        const FrameResult f = render({c, "count_discards=on"});
        ASSERT_TRUE(f.find<DiscardCounts>()) << c;
        std::printf("%s: invoked %llu, discarded %llu\n", c,
                    (unsigned long long)f.find<DiscardCounts>()->invoked,
                    (unsigned long long)f.find<DiscardCounts>()->discarded);
        counts.push_back(*f.find<DiscardCounts>());
    }
    for (size_t i = 1; i < counts.size(); ++i) {
        EXPECT_GT(counts[i].discarded, counts[i - 1].discarded);
        EXPECT_EQ(counts[i].invoked, counts[0].invoked);
    }
    EXPECT_FALSE(render({"count_discards=on", "prepass=off"}).find<DiscardCounts>());
}

// The new switches together with those that change which pipelines have the alpha test, at
// 4x: validation-clean; alpha-to-coverage leaves the counting pipeline nothing to discard.
TEST_F(Alpha, CombinationsAtFourSamplesAreValidationClean) {
    if (!has_msaa4()) GTEST_SKIP() << "the device has no 4x";
    for (const char* split : {"masked_split=on", "masked_split=off"})
        for (const char* compare : {"depth_compare=equal", "depth_compare=greater_or_equal"})
            for (const char* a2c : {"alpha_to_coverage=on", "alpha_to_coverage=off"}) {
                SCOPED_TRACE(std::string(split) + " " + compare + " " + a2c);
                const FrameResult f = render({"msaa=4", split, compare, a2c, "count_discards=on",
                                              "sample_shading=on", "count_fragments=on"});
                ASSERT_TRUE(f.find<DiscardCounts>());
                EXPECT_GT(f.find<DiscardCounts>()->invoked, 0u);
                if (std::string(a2c) == "alpha_to_coverage=on")
                    EXPECT_EQ(f.find<DiscardCounts>()->discarded, 0u);
                else
                    EXPECT_GT(f.find<DiscardCounts>()->discarded, 0u);
                EXPECT_EQ(renderer_->validation_message_count(), 0u);
            }
}

// material_alpha_cutoff raises one material's cutoff: the ramp card against the sky loses
// covered pixels, and the masked prepass pipeline discards more (invoked stays: late depth
// test); raising only the leaf material's cutoff leaves the ramp card's coverage as it was.
TEST_F(Alpha, PerMaterialCutoffLowersCoverageAndRaisesDiscards) {
    const scene::Camera up = ramp_card_against_the_sky(foliage_->camera);
    const FrameResult plain = render(up, {});
    const FrameResult ramp = render(up, {per_material({{kRamp, 0.9f}})});
    ASSERT_TRUE(plain.covered_pixels && ramp.covered_pixels);
    std::printf("covered: default %llu, %s=0.9 %llu\n", (unsigned long long)*plain.covered_pixels,
                kRamp, (unsigned long long)*ramp.covered_pixels);
    EXPECT_LT(*ramp.covered_pixels, *plain.covered_pixels);
    EXPECT_EQ(*render(up, {per_material({{kLeaf, 0.9f}})}).covered_pixels, *plain.covered_pixels);

    const FrameResult base = render_cut({"count_discards=on"});
    ASSERT_TRUE(base.find<DiscardCounts>());
    uint64_t previous = base.find<DiscardCounts>()->discarded;
    std::printf("discards: default invoked %llu, discarded %llu\n",
                (unsigned long long)base.find<DiscardCounts>()->invoked,
                (unsigned long long)previous);
    for (const char* material : {kRamp, kLeaf}) {
        const std::string knob = per_material({{material, 0.9f}});
        const FrameResult f = render_cut({knob, "count_discards=on"});
        ASSERT_TRUE(f.find<DiscardCounts>()) << knob;
        std::printf("discards: %s invoked %llu, discarded %llu\n", knob.c_str(),
                    (unsigned long long)f.find<DiscardCounts>()->invoked,
                    (unsigned long long)f.find<DiscardCounts>()->discarded);
        EXPECT_EQ(f.find<DiscardCounts>()->invoked, base.find<DiscardCounts>()->invoked) << knob;
        EXPECT_GT(f.find<DiscardCounts>()->discarded, base.find<DiscardCounts>()->discarded)
            << knob;
    }
    // Back to the default: the material uniforms are rewritten to no override.
    const FrameResult again = render_cut({"count_discards=on"});
    EXPECT_EQ(again.rgba8, base.rgba8);
    EXPECT_EQ(again.find<DiscardCounts>()->discarded, base.find<DiscardCounts>()->discarded);
}

// A per-material value for every MASK material equal to the global one gives the global
// override's image, bit for bit, on every path with the alpha test: the split and unsplit
// prepass, forward's MASK discard without the prepass and with greater_or_equal, shadows.
TEST_F(Alpha, PerMaterialValueEqualToTheGlobalGivesTheSameImage) {
    for (const char* path :
         {"prepass=on", "masked_split=off", "prepass=off", "depth_compare=greater_or_equal"}) {
        SCOPED_TRACE(path);
        const FrameResult global = render_cut({path, cutoff(0.7f), "count_discards=on"});
        const FrameResult each =
            render_cut({path, per_material({{kRamp, 0.7f}, {kLeaf, 0.7f}, {kGrass, 0.7f}}),
                        "count_discards=on"});
        EXPECT_EQ(each.rgba8, global.rgba8);
        EXPECT_EQ(each.covered_pixels, global.covered_pixels);
        ASSERT_EQ((each.find<DiscardCounts>() != nullptr),
                  (global.find<DiscardCounts>() != nullptr));
        if (global.find<DiscardCounts>()) {
            EXPECT_EQ(each.find<DiscardCounts>()->discarded,
                      global.find<DiscardCounts>()->discarded);
        }
        // And it changes the picture against the materials' own 0.5 at all.
        EXPECT_NE(global.rgba8, render_cut({path}).rgba8);
    }
}

// Precedence: the per-material value beats the global alpha_cutoff, which still applies to
// the materials not named.
TEST_F(Alpha, PerMaterialValueBeatsTheGlobalOne) {
    const FrameResult both =
        render_cut({cutoff(0.9f), per_material({{kRamp, 0.1f}}), "count_discards=on"});
    const FrameResult spelled_out = render_cut(
        {per_material({{kRamp, 0.1f}, {kLeaf, 0.9f}, {kGrass, 0.9f}}), "count_discards=on"});
    const FrameResult global = render_cut({cutoff(0.9f), "count_discards=on"});
    ASSERT_TRUE(both.find<DiscardCounts>() && spelled_out.find<DiscardCounts>() &&
                global.find<DiscardCounts>());
    std::printf("discarded: alpha_cutoff=0.9 %llu; with %s=0.1 %llu\n",
                (unsigned long long)global.find<DiscardCounts>()->discarded, kRamp,
                (unsigned long long)both.find<DiscardCounts>()->discarded);
    EXPECT_EQ(both.rgba8, spelled_out.rgba8);
    EXPECT_EQ(both.find<DiscardCounts>()->discarded, spelled_out.find<DiscardCounts>()->discarded);
    EXPECT_LT(both.find<DiscardCounts>()->discarded, global.find<DiscardCounts>()->discarded);
}

// A name that is no MASK material of the scene (unknown, or an opaque one) is one clear
// UsageError listing the masked materials, thrown before the frame begins: the next frame
// renders normally.
TEST_F(Alpha, UnknownMaterialNameIsAClearError) {
    for (const char* name : {"bogus", "ground"}) {
        SCOPED_TRACE(name);
        try {
            render_cut({std::string("material_alpha_cutoff=") + name + "=0.5"});
            ADD_FAILURE() << "no error";
        } catch (const UsageError& e) {
            EXPECT_EQ(std::string(e.what()),
                      std::string("material_alpha_cutoff: no masked material \"") + name +
                          "\" in foliage (masked: alpha_ramp, alpha_ramp_leaf, grass)");
        }
    }
    const FrameResult f = render_cut({per_material({{kRamp, 0.5f}})});
    EXPECT_EQ(f.rgba8, render_cut({}).rgba8);  // 0.5 is the ramp's own cutoff
}

}  // namespace
