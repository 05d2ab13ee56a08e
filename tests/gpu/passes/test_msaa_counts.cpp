// What lavapipe lacks and other devices have (an NVIDIA H200, for one): 2 and 8 samples, and
// the native nearest-sample depth resolve (VK_RESOLVE_MODE_MAX_BIT for reverse-Z, MIN_BIT for
// forward-Z). Each test runs where the device has the capability and skips naming it where it
// does not; on lavapipe (1x and 4x, SAMPLE_ZERO and AVERAGE only) they all skip.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "renderer/renderer.h"
#include "renderer/scene/loader.h"
#include "renderer/vk/capabilities.h"
#include "tests/gpu/passes/shared_renderer.h"

namespace {

using namespace ds;
using test::names;

constexpr uint32_t kMsaaCountsWidth = 240, kMsaaCountsHeight = 135;

class MsaaCounts : public test::SharedScene {
  protected:
    static void SetUpTestSuite() { set_up_with("edges"); }

    static bool has_samples(uint32_t count) {
        const auto& r = renderer_->device_report();
        return (r.color_sample_counts & r.depth_sample_counts & count) != 0;
    }
    static bool has_resolve(VkResolveModeFlagBits mode) {
        return (renderer_->device_report().depth_resolve_modes & mode) != 0;
    }
    static FrameResult render(const std::vector<std::string>& assignments, ReadBack read_back) {
        return renderer_->render(
            scene_->camera, test::settings_of(assignments),
            {.width = kMsaaCountsWidth, .height = kMsaaCountsHeight, .read_back = read_back});
    }

    // Renders edges at `samples` with every depth sample read back: the report's fields, the
    // silhouettes' edge pixels, and every resolved texel equal to its nearest sample.
    static void expect_nearest_resolve(uint32_t samples, bool reverse_z) {
        const FrameResult f = render(
            {"msaa=" + std::to_string(samples), reverse_z ? "reverse_z=on" : "reverse_z=off"},
            ReadBack::WithMsaaDepth);
        EXPECT_EQ(f.msaa.samples, samples);
        const bool native =
            has_resolve(reverse_z ? VK_RESOLVE_MODE_MAX_BIT : VK_RESOLVE_MODE_MIN_BIT);
        EXPECT_EQ(f.msaa.depth_resolve,
                  native ? (reverse_z ? "native-max" : "native-min") : "shader");
        ASSERT_TRUE(f.msaa.edge_pixels);
        EXPECT_GT(*f.msaa.edge_pixels, 0u);
        EXPECT_LT(*f.msaa.edge_pixels, uint64_t(kMsaaCountsWidth) * kMsaaCountsHeight);
        const size_t pixels = size_t(f.width) * f.height;
        ASSERT_EQ(f.msaa.resolved_depth.size(), pixels) << "depth format is not D32";
        ASSERT_EQ(f.msaa.depth_samples.size(), pixels * samples);
        size_t wrong = 0, not_sample_zero = 0;
        for (size_t p = 0; p < pixels; ++p) {
            const float* s = &f.msaa.depth_samples[p * samples];
            float nearest = s[0];
            for (size_t i = 1; i < samples; ++i)
                nearest = reverse_z ? std::max(nearest, s[i]) : std::min(nearest, s[i]);
            wrong += f.msaa.resolved_depth[p] != nearest;
            not_sample_zero += nearest != s[0];
        }
        std::printf("msaa=%u %s (%s): %zu pixels whose nearest sample is not sample 0\n", samples,
                    reverse_z ? "reverse-Z" : "forward-Z", f.msaa.depth_resolve.c_str(),
                    not_sample_zero);
        EXPECT_EQ(wrong, 0u);
        EXPECT_GT(not_sample_zero, 0u) << "the scene must tell nearest from sample zero";
        EXPECT_EQ(renderer_->validation_message_count(), 0u);
    }
};

TEST_F(MsaaCounts, TwoSamplesResolveToTheNearest) {
    if (!has_samples(VK_SAMPLE_COUNT_2_BIT))
        GTEST_SKIP() << "the device has no 2x (colour and depth sample counts)";
    expect_nearest_resolve(2, /*reverse_z=*/true);
    expect_nearest_resolve(2, /*reverse_z=*/false);
}

TEST_F(MsaaCounts, EightSamplesResolveToTheNearest) {
    if (!has_samples(VK_SAMPLE_COUNT_8_BIT))
        GTEST_SKIP() << "the device has no 8x (colour and depth sample counts)";
    expect_nearest_resolve(8, /*reverse_z=*/true);
    expect_nearest_resolve(8, /*reverse_z=*/false);
}

// With a native MAX (reverse-Z) or MIN (forward-Z) depth resolve the frame adds no
// depth_resolve pass: the prepass resolves inline, and the report names the native mode.
TEST_F(MsaaCounts, NativeDepthResolveAddsNoPass) {
    const bool max = has_resolve(VK_RESOLVE_MODE_MAX_BIT),
               min = has_resolve(VK_RESOLVE_MODE_MIN_BIT);
    if (!max && !min)
        GTEST_SKIP() << "no native MAX or MIN depth resolve (VK_KHR_depth_stencil_resolve)";
    if (!has_samples(VK_SAMPLE_COUNT_4_BIT)) GTEST_SKIP() << "the device has no 4x";
    for (const bool reverse_z : {true, false}) {
        if (!(reverse_z ? max : min)) continue;
        SCOPED_TRACE(reverse_z ? "reverse_z=on" : "reverse_z=off");
        const std::string z = reverse_z ? "reverse_z=on" : "reverse_z=off";
        const FrameResult one = render({z}, ReadBack::Yes);
        const FrameResult four = render({"msaa=4", z}, ReadBack::Yes);
        EXPECT_EQ(four.msaa.depth_resolve, reverse_z ? "native-max" : "native-min");
        EXPECT_EQ(names(four), names(one));
        const auto list = names(four);
        EXPECT_EQ(std::count(list.begin(), list.end(), "depth_resolve"), 0);
    }
    EXPECT_EQ(renderer_->validation_message_count(), 0u);
}

}  // namespace
