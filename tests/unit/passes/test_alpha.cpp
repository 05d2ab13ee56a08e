// Alpha-tested (MASK) geometry through the Renderer facade with validation on: alpha cutoff on
// the foliage scene, alpha-to-coverage and per-sample shading at 4x, and the prepass's
// discard counters (count_discards=on).
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "renderer/renderer.h"
#include "renderer/scene/loader.h"
#include "tests/unit/passes/shared_renderer.h"

namespace {

using namespace ds;

constexpr uint32_t kWidth = 240, kHeight = 135;

class Alpha : public test::SharedRenderer {
  protected:
    static void SetUpTestSuite() {
        SharedRenderer::SetUpTestSuite();
        foliage_ = new scene::Scene(scene::load_scene("foliage", Settings{}));
        renderer_->set_scene(*foliage_);
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
        return renderer_->render(camera, test::settings_of(assignments), kWidth, kHeight,
                                 ReadBack::Yes);
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

// Every card's alpha ramps across it: a higher cutoff cuts more of each card away. From the
// scene's own camera the backdrop and ground fill the frame (covered_pixels counts depth, not
// colour), so this looks up from the ground at the middle ramp card (x 0, z -3, 2 m tall)
// until its upper part stands against the sky above the backdrop: there what the cutoff
// removes is no longer covered.
TEST_F(Alpha, RaisingTheCutoffLowersCoveredPixels) {
    scene::Camera camera = foliage_->camera;
    camera.position = {0.0f, 0.15f, -1.6f};
    camera.forward = glm::normalize(glm::vec3(0.0f, 2.2f, -3.0f) - camera.position);
    camera.up = {0.0f, 1.0f, 0.0f};
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
    EXPECT_FALSE(plain.masked_discards);
    std::vector<DiscardCounts> counts;
    for (const char* c : {"alpha_cutoff=0.1", "alpha_cutoff=0.5", "alpha_cutoff=0.9"}) {
        const FrameResult f = render({c, "count_discards=on"});
        ASSERT_TRUE(f.masked_discards) << c;
        std::printf("%s: invoked %llu, discarded %llu\n", c,
                    (unsigned long long)f.masked_discards->invoked,
                    (unsigned long long)f.masked_discards->discarded);
        counts.push_back(*f.masked_discards);
    }
    for (size_t i = 1; i < counts.size(); ++i) {
        EXPECT_GT(counts[i].discarded, counts[i - 1].discarded);
        EXPECT_EQ(counts[i].invoked, counts[0].invoked);
    }
    EXPECT_FALSE(render({"count_discards=on", "prepass=off"}).masked_discards);
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
                ASSERT_TRUE(f.masked_discards);
                EXPECT_GT(f.masked_discards->invoked, 0u);
                if (std::string(a2c) == "alpha_to_coverage=on")
                    EXPECT_EQ(f.masked_discards->discarded, 0u);
                else
                    EXPECT_GT(f.masked_discards->discarded, 0u);
                EXPECT_EQ(renderer_->validation_message_count(), 0u);
            }
}

}  // namespace
