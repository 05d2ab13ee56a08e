// The view library's per-texel values (renderer/view): depth linearisation, texel readouts
// (depth, sky, normals, scalars, counts, colours) and the count heat map and its legend,
// against values worked out by hand.
#include <cstdint>
#include <cstdio>
#include <set>

#include <gtest/gtest.h>

#include "renderer/view/decode.h"
#include "renderer/view/heat.h"
#include "renderer/view/readout.h"
#include "tests/unit/view/view_test_images.h"

namespace {

using ds::InspectedImage;
using ds::graph::Semantic;
using ds::view::DecodedView;
using ds::view::ViewParams;
using namespace ds::view::test;  // Rgb, kNear, kFar, the image makers, pixel, manual

// --- linear_depth ------------------------------------------------------------------------

TEST(LinearDepth, RoundTripsReverseZ) {
    for (float d : {0.1f, 1.0f, 7.5f, 99.0f}) {
        const float stored = reverse_z_stored(d);
        EXPECT_NEAR(ds::view::linear_depth(stored, true, kNear, kFar), d, d * 1e-4f) << d;
    }
    EXPECT_NEAR(ds::view::linear_depth(1.0f, true, kNear, kFar), kNear, 1e-6f);
    EXPECT_NEAR(ds::view::linear_depth(0.0f, true, kNear, kFar), kFar, 1e-3f);
}

TEST(LinearDepth, RoundTripsForwardZ) {
    for (float d : {0.1f, 1.0f, 7.5f, 99.0f}) {
        const float stored = forward_z_stored(d);
        EXPECT_NEAR(ds::view::linear_depth(stored, false, kNear, kFar), d, d * 1e-3f) << d;
    }
    EXPECT_NEAR(ds::view::linear_depth(0.0f, false, kNear, kFar), kNear, 1e-6f);
}

TEST(LinearDepth, ConventionsMirrorEachOther) {
    // 0.9 is near under reverse-Z and far under forward-Z: a swapped convention shows.
    EXPECT_NEAR(ds::view::linear_depth(0.9f, true, kNear, kFar), 0.11110f, 1e-4f);
    EXPECT_NEAR(ds::view::linear_depth(0.9f, false, kNear, kFar), 0.99108f, 1e-3f);
    for (float s : {0.001f, 0.25f, 0.5f, 0.9f}) {
        EXPECT_NEAR(ds::view::linear_depth(s, true, kNear, kFar),
                    ds::view::linear_depth(1.0f - s, false, kNear, kFar), 1e-3f)
            << s;
    }
}

// --- readout -----------------------------------------------------------------------------

TEST(Readout, ReverseZDepthTexelGivesLinearDepth) {
    const float stored = reverse_z_stored(7.5f);
    auto image = scalar_row(Semantic::ReverseZDepth, VK_FORMAT_D32_SFLOAT, {0.0f, stored});
    auto r = ds::view::readout(image, 1, 0);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->x, 1u);
    EXPECT_EQ(r->y, 0u);
    EXPECT_EQ(r->channels, 1u);
    EXPECT_FLOAT_EQ(r->raw[0], stored);
    ASSERT_TRUE(r->linear_depth);
    EXPECT_NEAR(*r->linear_depth, 7.5f, 1e-3f);
    EXPECT_FALSE(r->sky);
    EXPECT_EQ(r->decoded_text, "linear depth 7.500 (scene units)");
    char expected_raw[32];
    std::snprintf(expected_raw, sizeof expected_raw, "%.7f", double(stored));
    EXPECT_EQ(r->raw_text, expected_raw);
    EXPECT_EQ(r->raw_text, "0.0123457");  // 0.1 * 92.5 / (99.9 * 7.5)
}

TEST(Readout, SkyTexelReportsSky) {
    auto reverse = scalar_row(Semantic::ReverseZDepth, VK_FORMAT_D32_SFLOAT, {0.0f});
    auto r = ds::view::readout(reverse, 0, 0);
    ASSERT_TRUE(r);
    EXPECT_TRUE(r->sky);
    EXPECT_FALSE(r->linear_depth);
    EXPECT_EQ(r->decoded_text, "sky (far plane)");
    EXPECT_EQ(r->raw_text, "0.0000000");

    auto forward = scalar_row(Semantic::ForwardZDepth, VK_FORMAT_D32_SFLOAT, {1.0f, 0.5f});
    auto f = ds::view::readout(forward, 0, 0);
    ASSERT_TRUE(f);
    EXPECT_TRUE(f->sky);
    EXPECT_EQ(f->decoded_text, "sky (far plane)");
    auto g = ds::view::readout(forward, 1, 0);
    ASSERT_TRUE(g);
    EXPECT_FALSE(g->sky);
    ASSERT_TRUE(g->linear_depth);
    EXPECT_NEAR(*g->linear_depth, 0.1998f, 1e-3f);
}

TEST(Readout, NormalDecodesToUnitVector) {
    auto image = make_image(Semantic::EncodedNormal, VK_FORMAT_A2B10G10R10_UNORM_PACK32, 3, 1,
                            {{0.5f, 1.0f, 0.5f, 1.0f},
                             {0.5f, 0.75f, 0.5f, 1.0f},   // not unit length: normalised
                             {0.5f, 0.5f, 0.5f, 1.0f}});  // zero vector
    auto r = ds::view::readout(image, 0, 0);
    ASSERT_TRUE(r);
    ASSERT_TRUE(r->normal);
    EXPECT_NEAR((*r->normal)[0], 0.0f, 1e-6f);
    EXPECT_NEAR((*r->normal)[1], 1.0f, 1e-6f);
    EXPECT_NEAR((*r->normal)[2], 0.0f, 1e-6f);
    EXPECT_EQ(r->decoded_text, "normal (0.00, 1.00, 0.00)");
    EXPECT_EQ(r->raw_text, "(0.500, 1.000, 0.500, 1.000)");
    EXPECT_EQ(r->channels, 4u);

    auto half = ds::view::readout(image, 1, 0);
    ASSERT_TRUE(half && half->normal);
    EXPECT_NEAR((*half->normal)[1], 1.0f, 1e-6f);

    auto zero = ds::view::readout(image, 2, 0);
    ASSERT_TRUE(zero);
    EXPECT_FALSE(zero->normal);

    auto tilted = make_image(Semantic::EncodedNormal, VK_FORMAT_A2B10G10R10_UNORM_PACK32, 1, 1,
                             {{1.0f, 0.5f, 0.0f, 1.0f}});  // (1, 0, -1) / sqrt 2
    auto t = ds::view::readout(tilted, 0, 0);
    ASSERT_TRUE(t && t->normal);
    EXPECT_NEAR((*t->normal)[0], 0.70710678f, 1e-5f);
    EXPECT_NEAR((*t->normal)[2], -0.70710678f, 1e-5f);
    EXPECT_EQ(t->decoded_text, "normal (0.71, 0.00, -0.71)");
}

TEST(Readout, ScalarsCountsAndColours) {
    auto rough = scalar_row(Semantic::UnormScalar, VK_FORMAT_R8_UNORM, {0.5f});
    rough.name = "roughness";
    auto r = ds::view::readout(rough, 0, 0);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->channels, 1u);
    EXPECT_EQ(r->decoded_text, "roughness 0.500");

    auto ao = scalar_row(Semantic::AO, VK_FORMAT_R8_UNORM, {0.83f});
    EXPECT_EQ(ds::view::readout(ao, 0, 0)->decoded_text, "AO 0.830");

    auto counts = scalar_row(Semantic::Count, VK_FORMAT_R32_UINT, {17.0f, 1.0f});
    auto c = ds::view::readout(counts, 0, 0);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->raw_text, "17");
    EXPECT_EQ(c->decoded_text, "17 fragments");
    EXPECT_EQ(c->channels, 1u);
    EXPECT_EQ(ds::view::readout(counts, 1, 0)->decoded_text, "1 fragment");

    auto hdr = make_image(Semantic::HdrColor, VK_FORMAT_R16G16B16A16_SFLOAT, 1, 1,
                          {{2.0f, 1.0f, 0.0f, 1.0f}});
    auto h = ds::view::readout(hdr, 0, 0);
    ASSERT_TRUE(h);
    EXPECT_EQ(h->raw_text, "(2.000, 1.000, 0.000, 1.000)");
    EXPECT_EQ(h->decoded_text, "linear rgb (2.000, 1.000, 0.000), luminance 1.140");
}

TEST(Readout, OutsideIsNone) {
    auto image = scalar_row(Semantic::UnormScalar, VK_FORMAT_R8_UNORM, {0.1f, 0.2f});
    EXPECT_TRUE(ds::view::readout(image, 1, 0));
    EXPECT_FALSE(ds::view::readout(image, 2, 0));
    EXPECT_FALSE(ds::view::readout(image, 0, 1));
    EXPECT_FALSE(ds::view::readout(image, UINT32_MAX, UINT32_MAX));
    InspectedImage empty;
    EXPECT_FALSE(ds::view::readout(empty, 0, 0));
    image.texels.resize(4);  // claims 2x1 but holds one texel
    EXPECT_FALSE(ds::view::readout(image, 1, 0));
}

// --- decode: counts ----------------------------------------------------------------------

TEST(DecodeCount, HeatMapFromBlackToTopColour) {
    std::vector<float> counts;
    for (int i = 0; i <= 10; ++i) counts.push_back(float(i));
    auto image = scalar_row(Semantic::Count, VK_FORMAT_R32_UINT, counts);
    DecodedView view = ds::view::decode(image, ViewParams{});
    EXPECT_EQ(view.unit, "count");
    EXPECT_FLOAT_EQ(view.black, 0.0f);
    EXPECT_FLOAT_EQ(view.white, 10.0f);
    EXPECT_EQ(pixel(view, 0), (Rgb{0, 0, 0}));
    EXPECT_EQ(pixel(view, 10), ds::view::heat_color(1.0f));
    EXPECT_EQ(pixel(view, 10), (Rgb{255, 255, 255}));
    std::set<Rgb> distinct;
    for (uint32_t i = 0; i <= 10; ++i) {
        distinct.insert(pixel(view, i));
        EXPECT_EQ(pixel(view, i), ds::view::count_color(float(i), 0.0f, 10.0f)) << i;
    }
    EXPECT_EQ(distinct.size(), 11u);
    // One fragment is clearly visible, not near-black.
    const Rgb one = pixel(view, 1);
    EXPECT_GT(one[0] + one[1] + one[2], 200);
}

// depth_precision: the step and the distance in readable units; the view is a log heat map
// whose range is in scene units, nothing drawn in the sky colour.
TEST(Readout, DepthStepSaysOneStepAtADistance) {
    const InspectedImage image =
        make_image(Semantic::DepthStep, VK_FORMAT_R32G32B32A32_SFLOAT, 3, 1,
                   {{0.00037f, 12.4f, 0, 0}, {0, 0, 0, 0}, {2.5e-6f, 1.5f, 0, 0}});
    EXPECT_EQ(ds::view::readout(image, 0, 0)->decoded_text, "one step = 0.37 mm at 12.4 m");
    EXPECT_EQ(ds::view::readout(image, 1, 0)->decoded_text, "nothing drawn");
    EXPECT_EQ(ds::view::readout(image, 2, 0)->decoded_text, "one step = 2.5 um at 1.5 m");
    const DecodedView view = ds::view::decode(image, ViewParams{});
    EXPECT_NEAR(view.black, 2.5e-6f, 1e-9f);
    EXPECT_NEAR(view.white, 0.00037f, 1e-7f);
    EXPECT_EQ(pixel(view, 1),
              (Rgb{ds::view::kSkyColor[0], ds::view::kSkyColor[1], ds::view::kSkyColor[2]}));
    EXPECT_NE(pixel(view, 0), pixel(view, 2));
}

// The log legend's stops: evenly spaced in log10 from black to white, coloured as decode
// colours those values.
TEST(Readout, LogLegendMatchesTheDepthStepColours) {
    const std::vector<ds::view::LegendStop> stops = ds::view::log_legend(1e-6f, 1e-3f, 4);
    ASSERT_EQ(stops.size(), 4u);
    EXPECT_NEAR(stops[0].count, 1e-6f, 1e-10f);
    EXPECT_NEAR(stops[1].count, 1e-5f, 1e-8f);
    EXPECT_NEAR(stops[3].count, 1e-3f, 1e-7f);
    const InspectedImage image =
        make_image(Semantic::DepthStep, VK_FORMAT_R32G32B32A32_SFLOAT, 4, 1,
                   {{1e-6f, 1, 0, 0}, {1e-5f, 1, 0, 0}, {1e-4f, 1, 0, 0}, {1e-3f, 1, 0, 0}});
    const DecodedView view = ds::view::decode(image, ViewParams{});
    for (uint32_t x = 0; x < 4; ++x) EXPECT_EQ(pixel(view, x), stops[x].rgb) << x;
    EXPECT_TRUE(ds::view::log_legend(0.0f, 1.0f).empty()) << "no log of 0";
}

TEST(DecodeCount, AutoFitIgnoresZeroAndManualClamps) {
    auto image = scalar_row(Semantic::Count, VK_FORMAT_R32_UINT, {0.0f, 3.0f, 6.0f, 12.0f});
    DecodedView view = ds::view::decode(image, manual(0.0f, 6.0f));
    EXPECT_EQ(pixel(view, 0), (Rgb{0, 0, 0}));
    EXPECT_EQ(pixel(view, 2), (Rgb{255, 255, 255}));
    EXPECT_EQ(pixel(view, 3), (Rgb{255, 255, 255}));        // above white clamps to the top colour
    EXPECT_EQ(pixel(view, 1), ds::view::heat_color(0.5f));  // 3 of 0..6

    auto zeros = scalar_row(Semantic::Count, VK_FORMAT_R32_UINT, {0.0f, 0.0f});
    DecodedView z = ds::view::decode(zeros, ViewParams{});
    EXPECT_FLOAT_EQ(z.black, 0.0f);
    EXPECT_FLOAT_EQ(z.white, 1.0f);
    EXPECT_EQ(pixel(z, 0), (Rgb{0, 0, 0}));
}

TEST(DecodeCount, LegendMatchesTheColours) {
    auto small = ds::view::count_legend(0.0f, 3.0f);
    ASSERT_EQ(small.size(), 4u);
    for (size_t i = 0; i < small.size(); ++i) {
        EXPECT_FLOAT_EQ(small[i].count, float(i));
        EXPECT_EQ(small[i].rgb, ds::view::count_color(float(i), 0.0f, 3.0f));
    }
    EXPECT_EQ(small[0].rgb, (Rgb{0, 0, 0}));
    EXPECT_EQ(small[3].rgb, (Rgb{255, 255, 255}));

    auto big = ds::view::count_legend(0.0f, 100.0f);
    ASSERT_EQ(big.size(), 7u);
    EXPECT_FLOAT_EQ(big[0].count, 0.0f);
    EXPECT_FLOAT_EQ(big[1].count, 1.0f);
    EXPECT_FLOAT_EQ(big[2].count, 20.0f);
    EXPECT_FLOAT_EQ(big.back().count, 100.0f);
    EXPECT_EQ(big.back().rgb, (Rgb{255, 255, 255}));
    for (size_t i = 1; i < big.size(); ++i) EXPECT_GT(big[i].count, big[i - 1].count);

    EXPECT_EQ(ds::view::count_legend(0.0f, 0.0f).size(), 1u);
}

}  // namespace
