// The view library's CPU decoding (renderer/view): depth, sky, ranges, auto-fit, channels,
// exposure, sRGB and image sizes, against values worked out by hand. Readouts, linear depth and
// the count heat map are in test_readout.cpp.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "renderer/view/decode.h"
#include "tests/unit/view/view_test_images.h"

namespace {

using ds::InspectedImage;
using ds::graph::Semantic;
using ds::view::DecodedView;
using ds::view::DepthView;
using ds::view::ViewParams;
using namespace ds::view::test;  // Rgb, kNear, kFar, the image makers, pixel, manual

Rgb grey(uint8_t v) {
    return {v, v, v};
}

int srgb_reference(float linear) {
    double v = std::clamp(double(linear), 0.0, 1.0);
    double s = v <= 0.0031308 ? v * 12.92 : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
    return int(std::lround(s * 255.0));
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

// zfight's view: counts above 0 keep their heat colour, the rest is the dimmed frame.
TEST(Decode, CountsOverTheDimmedFrame) {
    const InspectedImage counts =
        scalar_row(Semantic::Count, VK_FORMAT_R32_UINT, {0.0f, 1.0f, 0.0f, 3.0f});
    DecodedView view = ds::view::decode(counts, ViewParams{});
    const Rgb heat1 = pixel(view, 1), heat3 = pixel(view, 3);
    const std::vector<uint8_t> frame = {200, 100, 50, 255, 9, 9, 9, 255,
                                        10,  20,  30, 255, 9, 9, 9, 255};
    ds::view::overlay_counts(view, counts, frame, 0.5f);
    EXPECT_EQ(pixel(view, 0), (Rgb{100, 50, 25}));
    EXPECT_EQ(pixel(view, 1), heat1);
    EXPECT_EQ(pixel(view, 2), (Rgb{5, 10, 15}));
    EXPECT_EQ(pixel(view, 3), heat3);
    // A frame of another size changes nothing.
    const std::vector<uint8_t> small = {1, 2, 3, 255};
    DecodedView untouched = ds::view::decode(counts, ViewParams{});
    ds::view::overlay_counts(untouched, counts, small, 0.5f);
    EXPECT_EQ(untouched.rgba8, ds::view::decode(counts, ViewParams{}).rgba8);
}

// Surface ids: 0 is the sky colour, every other id a colour of its own that is stable.
TEST(Decode, SurfaceIdsGetStableDistinctColours) {
    const InspectedImage ids =
        scalar_row(Semantic::SurfaceId, VK_FORMAT_R32_UINT, {0.0f, 1.0f, 2.0f, 1.0f});
    const DecodedView view = ds::view::decode(ids, ViewParams{});
    const auto sky = ds::view::kSkyColor;
    EXPECT_EQ(pixel(view, 0), (Rgb{sky[0], sky[1], sky[2]}));
    EXPECT_EQ(pixel(view, 1), pixel(view, 3));
    EXPECT_NE(pixel(view, 1), pixel(view, 2));
    const auto c = ds::view::surface_color(1);
    EXPECT_EQ(pixel(view, 1), (Rgb{c[0], c[1], c[2]}));
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
