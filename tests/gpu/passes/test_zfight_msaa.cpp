// zfight at msaa > 1 (issue 24): the detector compares per sample, so on the zfight scene it
// finds the pairs it finds at 1x, each in about as many pixels, validation-clean, and every
// covered sample of a coplanar pair fights: the competitor image (summed over samples) holds
// `samples` times the 1x total. What would fail it (each tried): the quads are tilted, so
// their depth changes by thousands of ULPs between the samples of one pixel, and a detector
// or a bound reading sample 0's stored depth for every sample still finds every pair in
// about as many pixels, but in one or two samples per pixel (the total); one reading
// sample 0's winner makes the two triangles of one quad a pair along their shared diagonal.
// At msaa > 1 a pixel counts when any of its samples fights, so a pair gains the partly
// covered pixels along its overlap's edge: 640x360 keeps that near 5 % (10 % at 320x180).
// zfight_steps=8: lavapipe interpolates coplanar triangles with different diagonals up to 6
// ULPs apart (docs/history/issue-24.md), which at 4 steps leaves 1x pixels unflagged that 4x then
// finds.
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "renderer/passes/zfight.h"
#include "renderer/renderer.h"
#include "renderer/vk/capabilities.h"
#include "tests/gpu/passes/shared_renderer.h"

namespace {

using namespace ds;

constexpr uint32_t kWidth = 640, kHeight = 360;

// "a node|b node" -> pixels.
std::map<std::string, uint64_t> pixels_by_pair(const ZfightResult& z) {
    std::map<std::string, uint64_t> out;
    for (const ZfightPair& p : z.pairs) out[p.a.node + "|" + p.b.node] = p.pixels;
    return out;
}

// The zfight image's pixels with a competitor, and its sum.
struct Marked {
    uint64_t pixels = 0, competitors = 0;
};
Marked marked(const InspectedImage& image) {
    Marked m;
    for (size_t i = 0; i < image.texels.size(); i += 4) {
        m.pixels += image.texels[i] > 0.0f;
        m.competitors += uint64_t(image.texels[i]);
    }
    return m;
}

class ZfightMsaa : public test::SceneSwitching, public ::testing::WithParamInterface<int> {
  protected:
    FrameResult render_zfight(int samples, const InspectRequest& inspect = {}) {
        FrameResult f =
            render("zfight", {"zfight=on", "zfight_steps=8", "msaa=" + std::to_string(samples)},
                   kWidth, kHeight, ReadBack::Yes, inspect);
        EXPECT_EQ(renderer_->validation_message_count(), 0u) << "msaa " << samples;
        return f;
    }
};

TEST_P(ZfightMsaa, FindsThePairsOfOneSampleInAsManyPixels) {
    const int samples = GetParam();
    const vk::DeviceReport& device = renderer_->device_report();
    if (!(device.color_sample_counts & device.depth_sample_counts & uint32_t(samples)))
        GTEST_SKIP() << device.candidate.name << " offers no " << samples << "x msaa";
    if (!device.sample_rate_shading)
        GTEST_SKIP() << device.candidate.name << " has no sampleRateShading";

    const FrameResult one = render_zfight(1, {"zfight", 0});
    ASSERT_TRUE(one.find<ZfightResult>());
    const std::map<std::string, uint64_t> expected = pixels_by_pair(*one.find<ZfightResult>());
    ASSERT_GE(expected.size(), 6u) << "the six coplanar pairs at least";

    const FrameResult multi = render_zfight(samples, {"zfight", 0});
    ASSERT_TRUE(multi.find<ZfightResult>()) << (multi.skipped.empty() ? "" : multi.skipped.back());
    const ZfightResult& z = *multi.find<ZfightResult>();
    EXPECT_EQ(z.dropped, 0u);
    const std::map<std::string, uint64_t> found = pixels_by_pair(z);
    for (const auto& [pair, pixels] : expected) {
        const auto it = found.find(pair);
        ASSERT_NE(it, found.end())
            << pair << " (" << pixels << " pixels at 1x) lost at " << samples << "x";
        EXPECT_NEAR(double(it->second), double(pixels), 0.1 * double(pixels))
            << pair << " at " << samples << "x";
    }
    for (const auto& [pair, pixels] : found)
        EXPECT_TRUE(expected.contains(pair))
            << pair << " (" << pixels << " pixels) only at " << samples << "x";
    // The competitor image stays per pixel: its covered pixels are the result's.
    ASSERT_TRUE(multi.inspected);
    EXPECT_EQ(marked(*multi.inspected).pixels, z.pixels);
    ASSERT_TRUE(one.inspected);
    const double competitors = double(marked(*one.inspected).competitors);
    EXPECT_NEAR(double(marked(*multi.inspected).competitors), samples * competitors,
                0.1 * samples * competitors)
        << "competing samples at " << samples << "x against competitors at 1x";
}

INSTANTIATE_TEST_SUITE_P(Samples, ZfightMsaa, ::testing::Values(2, 4, 8),
                         [](const auto& info) { return "x" + std::to_string(info.param); });

}  // namespace
