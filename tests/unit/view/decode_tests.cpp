// The view library's CPU decoding (renderer/view): depth linearisation, sky, normals, counts,
// ranges, channels, exposure and texel readouts, against values worked out by hand.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <set>

#include <gtest/gtest.h>

#include "renderer/view/decode.h"
#include "renderer/view/heat.h"
#include "renderer/view/readout.h"

namespace {

using ds::InspectedImage;
using ds::graph::Semantic;
using ds::view::DecodedView;
using ds::view::DepthView;
using ds::view::ViewParams;
using Rgb = std::array<uint8_t, 3>;

constexpr float kNear = 0.1f, kFar = 100.0f;

// The renderer's projections (finite far): stored depth of a view distance d.
float reverse_z_stored(float d, float n = kNear, float f = kFar) {
    return n * (f - d) / ((f - n) * d);
}
float forward_z_stored(float d, float n = kNear, float f = kFar) {
    return f * (d - n) / ((f - n) * d);
}

// A width x height image whose texel i is texels[i] (rgba).
InspectedImage make_image(Semantic semantic, VkFormat format, uint32_t width, uint32_t height,
                          const std::vector<std::array<float, 4>>& texels) {
    InspectedImage image;
    image.name = "test";
    image.format = format;
    image.semantic = semantic;
    image.width = width;
    image.height = height;
    image.znear = kNear;
    image.zfar = kFar;
    image.reverse_z = semantic != Semantic::ForwardZDepth;
    for (const auto& t : texels) image.texels.insert(image.texels.end(), t.begin(), t.end());
    return image;
}

// A 1-row image of scalars in r (g = b = 0, a = 1, as a shader samples an R format).
InspectedImage scalar_row(Semantic semantic, VkFormat format, const std::vector<float>& values) {
    std::vector<std::array<float, 4>> texels;
    for (float v : values) texels.push_back({v, 0.0f, 0.0f, 1.0f});
    return make_image(semantic, format, uint32_t(values.size()), 1, texels);
}

Rgb pixel(const DecodedView& view, uint32_t x, uint32_t y = 0) {
    const size_t i = (size_t(y) * view.width + x) * 4;
    EXPECT_LT(i + 3, view.rgba8.size());
    EXPECT_EQ(view.rgba8[i + 3], 255) << "alpha at " << x << "," << y;
    return {view.rgba8[i], view.rgba8[i + 1], view.rgba8[i + 2]};
}

Rgb grey(uint8_t v) {
    return {v, v, v};
}

int srgb_reference(float linear) {
    double v = std::clamp(double(linear), 0.0, 1.0);
    double s = v <= 0.0031308 ? v * 12.92 : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
    return int(std::lround(s * 255.0));
}

ViewParams manual(float black, float white) {
    ViewParams p;
    p.auto_fit = false;
    p.black = black;
    p.white = white;
    return p;
}

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

// --- decode: depth -----------------------------------------------------------------------

TEST(DecodeDepth, AutoFitExcludesSkyAndMapsNearDark) {
    auto image =
        scalar_row(Semantic::ReverseZDepth, VK_FORMAT_D32_SFLOAT,
                   {reverse_z_stored(2.0f), 0.0f, reverse_z_stored(5.0f), reverse_z_stored(40.0f)});
    DecodedView view = ds::view::decode(image, ViewParams{});
    ASSERT_EQ(view.width, 4u);
    ASSERT_EQ(view.height, 1u);
    ASSERT_EQ(view.rgba8.size(), 16u);
    EXPECT_EQ(view.unit, "scene units");
    EXPECT_NEAR(view.black, 2.0f, 1e-3f);
    EXPECT_NEAR(view.white, 40.0f, 1e-2f);
    EXPECT_EQ(pixel(view, 0), grey(0));  // nearest: dark
    EXPECT_EQ(pixel(view, 1), ds::view::kSkyColor);
    EXPECT_EQ(pixel(view, 3), grey(255));  // farthest: bright
    // 5 of 2..40: (5 - 2) / 38 * 255 = 20.1
    EXPECT_NEAR(pixel(view, 2)[0], 20, 1);
}

TEST(DecodeDepth, RawShowsStoredValueAndSky) {
    const float s2 = reverse_z_stored(2.0f), s40 = reverse_z_stored(40.0f);
    auto image = scalar_row(Semantic::ReverseZDepth, VK_FORMAT_D32_SFLOAT, {s2, 0.0f, s40});
    ViewParams params;
    params.depth = DepthView::Raw;
    DecodedView view = ds::view::decode(image, params);
    EXPECT_EQ(view.unit, "raw depth");
    EXPECT_FLOAT_EQ(view.black, s40);
    EXPECT_FLOAT_EQ(view.white, s2);
    EXPECT_EQ(pixel(view, 0), grey(255));  // reverse-Z raw: near is the larger value
    EXPECT_EQ(pixel(view, 1), ds::view::kSkyColor);
    EXPECT_EQ(pixel(view, 2), grey(0));

    DecodedView fixed = ds::view::decode(image, [] {
        ViewParams p = manual(0.0f, 1.0f);
        p.depth = DepthView::Raw;
        return p;
    }());
    EXPECT_NEAR(pixel(fixed, 0)[0], std::lround(s2 * 255.0f), 1);
}

TEST(DecodeDepth, ForwardZSkyAndLinear) {
    auto image = scalar_row(Semantic::ForwardZDepth, VK_FORMAT_D32_SFLOAT,
                            {forward_z_stored(1.0f), 1.0f, forward_z_stored(11.0f)});
    DecodedView view = ds::view::decode(image, ViewParams{});
    EXPECT_NEAR(view.black, 1.0f, 1e-3f);
    EXPECT_NEAR(view.white, 11.0f, 0.05f);
    EXPECT_EQ(pixel(view, 0), grey(0));
    EXPECT_EQ(pixel(view, 1), ds::view::kSkyColor);
    EXPECT_EQ(pixel(view, 2), grey(255));
}

TEST(DecodeDepth, AllSkyUsesTheCameraRange) {
    auto image = scalar_row(Semantic::ReverseZDepth, VK_FORMAT_D32_SFLOAT, {0.0f, 0.0f});
    DecodedView view = ds::view::decode(image, ViewParams{});
    EXPECT_FLOAT_EQ(view.black, kNear);
    EXPECT_FLOAT_EQ(view.white, kFar);
    EXPECT_EQ(pixel(view, 0), ds::view::kSkyColor);
}

TEST(DecodeDepth, ManualLinearRangeClamps) {
    auto image =
        scalar_row(Semantic::ReverseZDepth, VK_FORMAT_D32_SFLOAT,
                   {reverse_z_stored(1.0f), reverse_z_stored(6.0f), reverse_z_stored(50.0f)});
    DecodedView view = ds::view::decode(image, manual(2.0f, 10.0f));
    EXPECT_FLOAT_EQ(view.black, 2.0f);
    EXPECT_FLOAT_EQ(view.white, 10.0f);
    EXPECT_EQ(pixel(view, 0), grey(0));
    EXPECT_NEAR(pixel(view, 1)[0], 128, 1);  // 6 is half of 2..10
    EXPECT_EQ(pixel(view, 2), grey(255));
}

TEST(DecodeDepth, ShadowDepthIsRaw) {
    auto image = scalar_row(Semantic::ShadowDepth, VK_FORMAT_D32_SFLOAT, {0.25f, 1.0f, 0.0f});
    DecodedView view = ds::view::decode(image, manual(0.0f, 1.0f));
    EXPECT_EQ(view.unit, "raw depth");
    EXPECT_EQ(pixel(view, 0), grey(64));
    EXPECT_EQ(pixel(view, 1), grey(255));  // no sky for an orthographic shadow map
    EXPECT_EQ(pixel(view, 2), grey(0));
}

// --- decode: scalars, ranges, channels ---------------------------------------------------

TEST(DecodeRange, ManualRangeClamps) {
    auto image =
        scalar_row(Semantic::UnormScalar, VK_FORMAT_R8_UNORM, {0.1f, 0.25f, 0.375f, 0.5f, 0.9f});
    DecodedView view = ds::view::decode(image, manual(0.25f, 0.5f));
    EXPECT_FLOAT_EQ(view.black, 0.25f);
    EXPECT_FLOAT_EQ(view.white, 0.5f);
    EXPECT_EQ(view.unit, "");
    EXPECT_EQ(pixel(view, 0), grey(0));
    EXPECT_EQ(pixel(view, 1), grey(0));
    EXPECT_EQ(pixel(view, 2), grey(128));
    EXPECT_EQ(pixel(view, 3), grey(255));
    EXPECT_EQ(pixel(view, 4), grey(255));
}

TEST(DecodeRange, AutoFitUsesMinMax) {
    auto image = scalar_row(Semantic::AO, VK_FORMAT_R8_UNORM, {0.75f, 0.25f, 0.5f});
    DecodedView view = ds::view::decode(image, ViewParams{});
    EXPECT_FLOAT_EQ(view.black, 0.25f);
    EXPECT_FLOAT_EQ(view.white, 0.75f);
    EXPECT_EQ(pixel(view, 0), grey(255));
    EXPECT_EQ(pixel(view, 1), grey(0));
    EXPECT_EQ(pixel(view, 2), grey(128));
}

TEST(DecodeRange, FlatImageIsMidGreyAndNaNIsMagenta) {
    auto flat = scalar_row(Semantic::AO, VK_FORMAT_R8_UNORM, {0.7f, 0.7f});
    DecodedView view = ds::view::decode(flat, ViewParams{});
    EXPECT_FLOAT_EQ(view.black, 0.7f);
    EXPECT_FLOAT_EQ(view.white, 0.7f);
    EXPECT_EQ(pixel(view, 0), grey(128));

    auto nan = scalar_row(Semantic::UnormScalar, VK_FORMAT_R16_SFLOAT,
                          {0.2f, std::nanf(""), 0.8f, INFINITY});
    DecodedView v = ds::view::decode(nan, ViewParams{});
    EXPECT_FLOAT_EQ(v.black, 0.2f);  // non-finite texels do not take part in the fit
    EXPECT_FLOAT_EQ(v.white, 0.8f);
    EXPECT_EQ(pixel(v, 1), ds::view::kNonFiniteColor);
    EXPECT_EQ(pixel(v, 3), ds::view::kNonFiniteColor);
    EXPECT_EQ(pixel(v, 2), grey(255));
}

TEST(DecodeRange, EqualManualBlackAndWhiteIsAThreshold) {
    auto image = scalar_row(Semantic::UnormScalar, VK_FORMAT_R8_UNORM, {0.3f, 0.5f, 0.51f});
    DecodedView view = ds::view::decode(image, manual(0.5f, 0.5f));
    EXPECT_EQ(pixel(view, 0), grey(0));
    EXPECT_EQ(pixel(view, 1), grey(0));
    EXPECT_EQ(pixel(view, 2), grey(255));
}

TEST(DecodeChannels, IsolationShowsOneChannelAsGrey) {
    auto other = make_image(Semantic::Other, VK_FORMAT_R32G32B32A32_SFLOAT, 1, 1,
                            {{0.2f, 0.4f, 0.6f, 0.8f}});
    ViewParams params = manual(0.0f, 1.0f);
    EXPECT_EQ(pixel(ds::view::decode(other, params), 0), (Rgb{51, 102, 153}));
    for (int c = 0; c < 4; ++c) {
        params.channel = c;
        const uint8_t expected[] = {51, 102, 153, 204};
        EXPECT_EQ(pixel(ds::view::decode(other, params), 0), grey(expected[c])) << c;
    }

    auto normals = make_image(Semantic::EncodedNormal, VK_FORMAT_A2B10G10R10_UNORM_PACK32, 1, 1,
                              {{0.5f, 1.0f, 0.0f, 1.0f}});
    ViewParams all;
    EXPECT_EQ(pixel(ds::view::decode(normals, all), 0), (Rgb{128, 255, 0}));  // as stored
    ViewParams g;
    g.channel = 1;
    EXPECT_EQ(pixel(ds::view::decode(normals, g), 0), grey(255));
    g.channel = 2;
    EXPECT_EQ(pixel(ds::view::decode(normals, g), 0), grey(0));

    // A colour's alpha is shown as stored, without exposure or sRGB encoding.
    auto hdr = make_image(Semantic::HdrColor, VK_FORMAT_R16G16B16A16_SFLOAT, 1, 1,
                          {{4.0f, 4.0f, 4.0f, 0.25f}});
    ViewParams a;
    a.channel = 3;
    a.exposure = 3.0f;
    EXPECT_EQ(pixel(ds::view::decode(hdr, a), 0), grey(64));
}

TEST(DecodeChannels, OtherAutoFitsOverShownChannels) {
    auto two = make_image(Semantic::Other, VK_FORMAT_R32G32_SFLOAT, 2, 1,
                          {{-1.0f, 0.0f, 0.0f, 1.0f}, {1.0f, 3.0f, 0.0f, 1.0f}});
    DecodedView view = ds::view::decode(two, ViewParams{});
    EXPECT_FLOAT_EQ(view.black, -1.0f);
    EXPECT_FLOAT_EQ(view.white, 3.0f);
    EXPECT_EQ(pixel(view, 0), (Rgb{0, 64, 0}));
    EXPECT_EQ(pixel(view, 1), (Rgb{128, 255, 0}));

    auto one = make_image(Semantic::Other, VK_FORMAT_R32_SFLOAT, 2, 1,
                          {{2.0f, 0.0f, 0.0f, 1.0f}, {4.0f, 0.0f, 0.0f, 1.0f}});
    DecodedView g = ds::view::decode(one, ViewParams{});
    EXPECT_EQ(pixel(g, 0), grey(0));  // one channel: grey, not red
    EXPECT_EQ(pixel(g, 1), grey(255));
}

// --- decode: colours ---------------------------------------------------------------------

TEST(DecodeColour, HdrExposurePlusOneDoublesBeforeEncoding) {
    auto base = make_image(Semantic::HdrColor, VK_FORMAT_R16G16B16A16_SFLOAT, 2, 1,
                           {{0.1f, 0.2f, 0.3f, 1.0f}, {0.8f, 0.001f, 0.0f, 1.0f}});
    auto doubled = make_image(Semantic::HdrColor, VK_FORMAT_R16G16B16A16_SFLOAT, 2, 1,
                              {{0.2f, 0.4f, 0.6f, 1.0f}, {1.6f, 0.002f, 0.0f, 1.0f}});
    ViewParams plus_one;
    plus_one.exposure = 1.0f;
    DecodedView a = ds::view::decode(base, plus_one);
    DecodedView b = ds::view::decode(doubled, ViewParams{});
    EXPECT_EQ(a.rgba8, b.rgba8);
    DecodedView unexposed = ds::view::decode(base, ViewParams{});
    EXPECT_NE(unexposed.rgba8, a.rgba8);

    const Rgb p = pixel(a, 0);
    EXPECT_NEAR(p[0], srgb_reference(0.2f), 1);
    EXPECT_NEAR(p[1], srgb_reference(0.4f), 1);
    EXPECT_NEAR(p[2], srgb_reference(0.6f), 1);
    EXPECT_EQ(pixel(a, 1)[0], 255);                          // 1.6 clamps
    EXPECT_NEAR(pixel(a, 1)[1], srgb_reference(0.002f), 1);  // linear segment of the curve
    EXPECT_EQ(pixel(a, 1)[2], 0);
    EXPECT_EQ(a.unit, "");
}

TEST(DecodeColour, SrgbLutMatchesTheCurve) {
    std::vector<std::array<float, 4>> texels;
    for (int i = 0; i <= 1000; ++i) texels.push_back({float(i) / 1000.0f, 0.0f, 0.0f, 1.0f});
    auto image = make_image(Semantic::HdrColor, VK_FORMAT_R16G16B16A16_SFLOAT, 1001, 1, texels);
    DecodedView view = ds::view::decode(image, ViewParams{});
    for (uint32_t i = 0; i <= 1000; ++i) {
        EXPECT_NEAR(pixel(view, i)[0], srgb_reference(float(i) / 1000.0f), 1) << i;
    }
    EXPECT_EQ(pixel(view, 0)[0], 0);
    EXPECT_EQ(pixel(view, 1000)[0], 255);
    EXPECT_EQ(pixel(view, 500)[0], srgb_reference(0.5f));  // 188, far from linear 128
}

TEST(DecodeColour, LdrIsAsStoredUnlessTheFormatIsSrgb) {
    auto unorm =
        make_image(Semantic::LdrColor, VK_FORMAT_R8G8B8A8_UNORM, 1, 1, {{0.5f, 1.0f, 0.0f, 1.0f}});
    EXPECT_EQ(pixel(ds::view::decode(unorm, ViewParams{}), 0), (Rgb{128, 255, 0}));
    auto srgb = make_image(Semantic::LdrColor, VK_FORMAT_R8G8B8A8_SRGB, 1, 1,
                           {{0.21586f, 1.0f, 0.0f, 1.0f}});  // sampled (linear) value of 128
    EXPECT_EQ(pixel(ds::view::decode(srgb, ViewParams{}), 0), (Rgb{128, 255, 0}));
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

// --- decode: sizes -----------------------------------------------------------------------

TEST(Decode, MalformedImageDecodesEmpty) {
    auto image = scalar_row(Semantic::AO, VK_FORMAT_R8_UNORM, {0.5f, 0.5f});
    image.texels.pop_back();
    DecodedView view = ds::view::decode(image, ViewParams{});
    EXPECT_EQ(view.width, 0u);
    EXPECT_TRUE(view.rgba8.empty());
}

TEST(Decode, HdSizedImagesDecodeToFullSize) {
    constexpr uint32_t w = 1280, h = 720;
    InspectedImage depth;
    depth.semantic = Semantic::ReverseZDepth;
    depth.format = VK_FORMAT_D32_SFLOAT;
    depth.width = w;
    depth.height = h;
    depth.znear = kNear;
    depth.zfar = kFar;
    depth.texels.resize(size_t(w) * h * 4);
    for (size_t i = 0; i < size_t(w) * h; ++i) {
        depth.texels[i * 4] = (i % 7 == 0) ? 0.0f : reverse_z_stored(1.0f + float(i % 97));
    }
    InspectedImage hdr = depth;
    hdr.semantic = Semantic::HdrColor;
    hdr.format = VK_FORMAT_R16G16B16A16_SFLOAT;
    for (size_t i = 0; i < hdr.texels.size(); ++i) hdr.texels[i] = float(i % 300) / 100.0f;
    InspectedImage counts = depth;
    counts.semantic = Semantic::Count;
    counts.format = VK_FORMAT_R32_UINT;
    for (size_t i = 0; i < size_t(w) * h; ++i) counts.texels[i * 4] = float(i % 13);

    DecodedView view;  // reused, as the viewer does every frame
    for (const InspectedImage* image : {&depth, &hdr, &counts}) {
        const auto start = std::chrono::steady_clock::now();
        ds::view::decode_into(*image, ViewParams{}, view);
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        std::printf("decode %ux%u semantic %d: %.2f ms\n", w, h, int(image->semantic), ms);
        EXPECT_EQ(view.width, w);
        EXPECT_EQ(view.height, h);
        EXPECT_EQ(view.rgba8.size(), size_t(w) * h * 4);
    }
}

TEST(Formats, Channels) {
    EXPECT_EQ(ds::view::format_channels(VK_FORMAT_D32_SFLOAT), 1u);
    EXPECT_EQ(ds::view::format_channels(VK_FORMAT_R8_UNORM), 1u);
    EXPECT_EQ(ds::view::format_channels(VK_FORMAT_R32_UINT), 1u);
    EXPECT_EQ(ds::view::format_channels(VK_FORMAT_R16G16_SFLOAT), 2u);
    EXPECT_EQ(ds::view::format_channels(VK_FORMAT_B10G11R11_UFLOAT_PACK32), 3u);
    EXPECT_EQ(ds::view::format_channels(VK_FORMAT_A2B10G10R10_UNORM_PACK32), 4u);
    EXPECT_EQ(ds::view::format_channels(VK_FORMAT_R16G16B16A16_SFLOAT), 4u);
}

}  // namespace
