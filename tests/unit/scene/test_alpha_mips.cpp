// scene/alpha_mips.h and alpha_coverage.h: the CPU box chain (sizes, rounding, sRGB colour in
// linear light), each level's alpha coverage worked out by hand, Castaño's preserve keeping
// every level near level 0's coverage, baseColorFactor.a, the effective cutoff's precedence.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "renderer/scene/alpha_coverage.h"
#include "renderer/scene/alpha_mips.h"
#include "renderer/settings/settings.h"

namespace ds::scene {
namespace {

// A w x h RGBA8 image whose texel (x, y) is alpha(x, y), colour grey 100.
template <typename AlphaFn>
MipImage image_of(uint32_t w, uint32_t h, AlphaFn alpha) {
    MipImage m{w, h, std::vector<uint8_t>(size_t(w) * h * 4, 100)};
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) m.rgba8[(size_t(y) * w + x) * 4 + 3] = alpha(x, y);
    return m;
}

std::vector<MipImage> chain_of(const MipImage& level0, bool srgb = false) {
    return box_mip_chain(level0.width, level0.height, level0.rgba8, srgb);
}

TEST(AlphaMips, BoxFilterAveragesTwoByTwo) {
    const MipImage src{2, 2, {0, 10, 100, 255, 4, 10, 100, 255, 8, 10, 100, 255, 12, 10, 100, 0}};
    const MipImage out = downsample_rgba8(src, /*srgb=*/false);
    ASSERT_EQ(out.rgba8.size(), 4u);
    EXPECT_EQ(out.rgba8[0], 6);  // (0 + 4 + 8 + 12 + 2) / 4, rounded
    EXPECT_EQ(out.rgba8[1], 10);
    EXPECT_EQ(out.rgba8[2], 100);
    EXPECT_EQ(out.rgba8[3], 191);  // (3 * 255 + 0 + 2) / 4
}

TEST(AlphaMips, SrgbColourAveragesInLinearLightAndAlphaStaysLinear) {
    // Black and white texels: half the light is sRGB 188, not the encoded mean 128.
    const MipImage src{2, 1, {0, 0, 0, 0, 255, 255, 255, 255}};
    const MipImage srgb = downsample_rgba8(src, true);
    const MipImage linear = downsample_rgba8(src, false);
    EXPECT_EQ(srgb.rgba8[0], 188);
    EXPECT_EQ(srgb.rgba8[3], 128);  // alpha: (0 + 255 + 255 + 0 + 2) / 4 with the clamp
    EXPECT_EQ(linear.rgba8[0], 128);
    EXPECT_EQ(linear.rgba8[3], 128);
}

TEST(AlphaMips, NonPowerOfTwoChainsHalveFlooredDownToOneByOne) {
    const MipImage src = image_of(100, 30, [](uint32_t x, uint32_t) { return uint8_t(x); });
    const std::vector<MipImage> chain = chain_of(src);
    const uint32_t sizes[][2] = {{100, 30}, {50, 15}, {25, 7}, {12, 3}, {6, 1}, {3, 1}, {1, 1}};
    ASSERT_EQ(chain.size(), 7u);
    EXPECT_EQ(mip_chain_length(100, 30), 7u);
    for (size_t i = 0; i < chain.size(); ++i) {
        EXPECT_EQ(chain[i].width, sizes[i][0]) << i;
        EXPECT_EQ(chain[i].height, sizes[i][1]) << i;
        EXPECT_EQ(chain[i].rgba8.size(), size_t(sizes[i][0]) * sizes[i][1] * 4) << i;
    }
    // Odd sizes: floor halving leaves the last column out (3 -> 1 reads columns 0 and 1).
    const MipImage odd = downsample_rgba8(
        image_of(3, 1, [](uint32_t x, uint32_t) { return uint8_t(x == 2 ? 255 : 100); }), false);
    EXPECT_EQ(odd.rgba8[3], 100);
}

// Column 0 of a 4x4 image has alpha 200 (0.784), the rest 0. Cutoff 0.5: level 0 passes 4 of
// 16 texels; level 1's left texels average (200 + 0 + 200 + 0 + 2) / 4 = 100 (0.39): none pass.
// Level 2 averages level 1's four texels (100, 0, 100, 0) to 50: none.
TEST(AlphaMips, CoveragePerLevelByHand) {
    const MipImage line = image_of(4, 4, [](uint32_t x, uint32_t) { return uint8_t(x ? 0 : 200); });
    const std::vector<LevelCoverage> c = chain_coverage(chain_of(line), 0.5f, 1.0f);
    ASSERT_EQ(c.size(), 3u);
    EXPECT_DOUBLE_EQ(c[0].coverage, 0.25);
    EXPECT_DOUBLE_EQ(c[1].coverage, 0.0);
    EXPECT_DOUBLE_EQ(c[1].relative, 0.0);
    EXPECT_EQ(c[1].width, 2u);
    EXPECT_EQ(c[2].level, 2u);
    // A 1-texel checker of 255 and 0: half passes; every 2x2 block averages to 128 (0.502).
    const MipImage checker =
        image_of(4, 4, [](uint32_t x, uint32_t y) { return uint8_t((x + y) % 2 ? 255 : 0); });
    const std::vector<LevelCoverage> k = chain_coverage(chain_of(checker), 0.5f, 1.0f);
    EXPECT_DOUBLE_EQ(k[0].coverage, 0.5);
    EXPECT_DOUBLE_EQ(k[1].coverage, 1.0);
    EXPECT_DOUBLE_EQ(k[1].relative, 2.0);
    // The test is alpha >= cutoff, in float: 128 / 255 passes 0.5, 127 / 255 does not.
    EXPECT_DOUBLE_EQ(
        alpha_coverage(image_of(1, 1, [](auto, auto) { return uint8_t(128); }), 0.5f, 1.0f), 1.0);
    EXPECT_DOUBLE_EQ(
        alpha_coverage(image_of(1, 1, [](auto, auto) { return uint8_t(127); }), 0.5f, 1.0f), 0.0);
}

TEST(AlphaMips, FactorAlphaScalesTheTestedAlpha) {
    const MipImage a200 = image_of(2, 2, [](uint32_t, uint32_t) { return uint8_t(200); });
    EXPECT_DOUBLE_EQ(alpha_coverage(a200, 0.5f, 1.0f), 1.0);   // 0.784
    EXPECT_DOUBLE_EQ(alpha_coverage(a200, 0.5f, 0.5f), 0.0);   // 0.392
    EXPECT_DOUBLE_EQ(alpha_coverage(a200, 0.35f, 0.5f), 1.0);  // 0.392 >= 0.35
}

uint32_t mix(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    return x ^ (x >> 16);
}
float hash01(uint32_t k, uint32_t salt) {
    return float(mix(k * 0x9e3779b9u + salt * 0x85ebca6bu + 1u) & 0xffffffu) / float(0xffffff);
}

// Grass: w / 4 tapering blades, 1.2 to 3 texels wide at the root, edges antialiased, so the
// levels hold many alpha values: what a box chain thins.
MipImage blades(uint32_t w, uint32_t h) {
    MipImage m = image_of(w, h, [](uint32_t, uint32_t) { return uint8_t(0); });
    for (uint32_t k = 0; k < w / 4; ++k) {
        const float root = hash01(k, 1) * float(w), top = (0.3f + 0.6f * hash01(k, 2)) * float(h);
        const float half = 0.6f + 0.9f * hash01(k, 3), lean = (hash01(k, 4) - 0.5f) * 0.4f;
        for (uint32_t y = 0; y < h; ++y) {
            const float t = (float(h) - float(y) - 0.5f) / top;  // 0 at the root, 1 at the tip
            if (t < 0.0f || t > 1.0f) continue;
            const float centre = root + lean * t * float(h) * 0.3f;
            for (uint32_t x = 0; x < w; ++x) {
                const float d = std::abs(float(x) + 0.5f - centre);
                const float a = std::clamp(half * (1.0f - t) - d + 0.5f, 0.0f, 1.0f);
                uint8_t& texel = m.rgba8[(size_t(y) * w + x) * 4 + 3];
                texel = std::max(texel, uint8_t(std::lround(a * 255.0f)));
            }
        }
    }
    return m;
}

void expect_preserved(uint32_t w, uint32_t h, float cutoff, float factor) {
    SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h) + " cutoff " + std::to_string(cutoff) +
                 " factor " + std::to_string(factor));
    const std::vector<MipImage> box = chain_of(blades(w, h), /*srgb=*/true);
    std::vector<MipImage> kept = box;
    preserve_alpha_coverage(kept, cutoff, factor);
    const std::vector<LevelCoverage> before = chain_coverage(box, cutoff, factor);
    const std::vector<LevelCoverage> after = chain_coverage(kept, cutoff, factor);
    ASSERT_GT(after[0].coverage, 0.0);
    EXPECT_EQ(kept[0].rgba8, box[0].rgba8) << "level 0 is as given";
    bool box_fell = false;
    for (size_t i = 1; i < kept.size(); ++i) {
        if (kept[i].width < 16 || kept[i].height < 16) continue;
        box_fell = box_fell || before[i].relative < 0.8;
        EXPECT_NEAR(after[i].relative, 1.0, 0.02) << "level " << i;
        for (size_t t = 0; t < kept[i].rgba8.size(); ++t) {
            if (t % 4 != 3) {
                ASSERT_EQ(kept[i].rgba8[t], box[i].rgba8[t]) << "colour unchanged";
            }
        }
    }
    EXPECT_TRUE(box_fell) << "the box chain should thin these blades";
}

// Levels of at least 16x16: smaller ones have too few texels to hit a share closely.
TEST(AlphaMips, PreserveKeepsEveryLevelWithinTwoPercentOfLevelZero) {
    expect_preserved(256, 256, 0.5f, 1.0f);
    expect_preserved(256, 200, 0.5f, 1.0f);  // non-power-of-two
    expect_preserved(250, 130, 0.6f, 1.0f);  // odd sizes: 125x65, 62x32, 31x16
    expect_preserved(100, 60, 0.5f, 1.0f);   // 50x30, 25x15 (too small), ...
    expect_preserved(256, 256, 0.25f, 0.5f);
}

// The factor is part of the test preserve matches: halving it and the cutoff gives the same
// test (x 0.5 is exact in float), so the same chain; halving the factor alone does not.
TEST(AlphaMips, PreserveHonoursTheFactor) {
    const MipImage grass = blades(128, 128);
    std::vector<MipImage> a = chain_of(grass), b = a, c = a;
    preserve_alpha_coverage(a, 0.5f, 1.0f);
    preserve_alpha_coverage(b, 0.25f, 0.5f);
    preserve_alpha_coverage(c, 0.5f, 0.8f);
    for (size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].rgba8, b[i].rgba8) << "level " << i;
    EXPECT_NE(a[1].rgba8, c[1].rgba8);
    const std::vector<LevelCoverage> kept = chain_coverage(c, 0.5f, 0.8f);
    EXPECT_NEAR(kept[1].relative, 1.0, 0.02);
}

TEST(AlphaMips, PreserveKeepsALevelThatAlreadyMatches) {
    const MipImage checker =
        image_of(8, 8, [](uint32_t x, uint32_t) { return uint8_t(x < 4 ? 255 : 0); });
    std::vector<MipImage> chain = chain_of(checker);
    const std::vector<MipImage> box = chain;
    const std::vector<float> scales = preserve_alpha_coverage(chain, 0.5f, 1.0f);
    EXPECT_EQ(scales[1], 1.0f);
    EXPECT_EQ(chain[1].rgba8, box[1].rgba8);
}

TEST(AlphaCoverage, EffectiveCutoffPrecedence) {
    Material m;
    m.alpha_cutoff = 0.5f;
    EXPECT_FLOAT_EQ(effective_alpha_cutoff(m, std::nullopt, std::nullopt), 0.5f);
    EXPECT_FLOAT_EQ(effective_alpha_cutoff(m, std::nullopt, 0.2f), 0.2f);
    EXPECT_FLOAT_EQ(effective_alpha_cutoff(m, 0.7f, 0.2f), 0.7f);

    Scene scene;
    scene.materials.resize(3);
    scene.materials[0].name = "leaf";
    scene.materials[0].alpha_mode = AlphaMode::Mask;
    scene.materials[1].name = "bark";
    scene.materials[1].alpha_mode = AlphaMode::Mask;
    scene.materials[2].name = "leaf";  // OPAQUE: material_alpha_cutoff names MASK materials
    Settings s;
    s.apply("alpha_cutoff=0.25");
    s.apply("material_alpha_cutoff=leaf=0.75");
    EXPECT_EQ(effective_alpha_cutoffs(scene, s), (std::vector<float>{0.75f, 0.25f, 0.25f}));
    EXPECT_EQ(alpha_mip_mode(s), AlphaMipMode::Box);
    s.apply("alpha_mip_coverage=preserve");
    EXPECT_EQ(alpha_mip_mode(s), AlphaMipMode::Preserve);
}

TEST(AlphaCoverage, WorstDropLooksAtLevelsOfTheMinimumSizeOnly) {
    const std::vector<LevelCoverage> levels = {
        {0, 64, 64, 0.4, 1.0}, {1, 32, 32, 0.36, 0.9}, {2, 16, 16, 0.2, 0.5}, {3, 8, 8, 0.0, 0.0}};
    const auto worst = worst_coverage_drop(levels, 16);
    ASSERT_TRUE(worst);
    EXPECT_EQ(worst->level, 2u);
    EXPECT_DOUBLE_EQ(worst->drop, 0.5);
    EXPECT_FALSE(worst_coverage_drop({levels[0]}, 16));
}

}  // namespace
}  // namespace ds::scene
