// Overlays, count images by pass and the wasted view (renderer/view/overlay.h): hand-made
// images, expectations from decode's own heat colours and the blend written out here.
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/view/heat.h"
#include "renderer/view/overlay.h"
#include "tests/unit/view/view_test_images.h"

namespace ds::view::test {
namespace {

using graph::Semantic;

// The blend an overlay promises, in double: base + (over - base) * opacity, rounded.
uint8_t expected_blend(uint8_t base, uint8_t over, double opacity) {
    return uint8_t(std::lround(double(base) + (double(over) - double(base)) * opacity));
}

// A decoded LDR image of one colour per texel (what the final image decodes to).
DecodedView colours(const std::vector<Rgb>& texels) {
    std::vector<std::array<float, 4>> t;
    for (const Rgb& c : texels) t.push_back({c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f, 1.0f});
    return decode(
        make_image(Semantic::LdrColor, VK_FORMAT_R8G8B8A8_UNORM, uint32_t(t.size()), 1, t),
        ViewParams{});
}

TEST(CountImages, TheNameGivesPassAndKind) {
    const auto prepass = count_image_name("depth_prepass_discarded");
    ASSERT_TRUE(prepass);
    EXPECT_EQ(prepass->pass, "depth_prepass");
    EXPECT_EQ(prepass->kind, "discarded");
    EXPECT_EQ(count_image_name("forward_counts")->kind, "counts");
    EXPECT_EQ(count_image_name("shadow_rasterized")->pass, "shadow");
    EXPECT_EQ(count_image_name("forward_wasted")->kind, "wasted");
    EXPECT_FALSE(count_image_name("zfight"));
    EXPECT_FALSE(count_image_name("equal_check"));
    EXPECT_FALSE(count_image_name("_counts"));
    EXPECT_FALSE(count_image_name("forward_normals"));
    EXPECT_EQ(count_image("decals", kWastedKind), "decals_wasted");
}

// A known count image at a known opacity over the final image: the count's heat colour (on
// the 0..max scale decode fits) blended over the final pixel; nothing counted stays as is.
TEST(Overlays, ACountImageBlendsItsHeatColourWhereItCounted) {
    const std::vector<Rgb> final_rgb{{200, 100, 50}, {10, 20, 30}, {90, 90, 90}, {0, 255, 0}};
    DecodedView view = colours(final_rgb);
    const InspectedImage counts =
        scalar_row(Semantic::Count, VK_FORMAT_R32_UINT, {0.0f, 1.0f, 4.0f, 2.0f});
    const DecodedView heat = decode(counts, ViewParams{});
    const float opacity = 0.375f;  // exact in binary: float and double blends agree
    ASSERT_TRUE(blend_overlay(view, heat, counts, opacity));
    EXPECT_EQ(pixel(view, 0), final_rgb[0]) << "0 counted: transparent";
    for (uint32_t x = 1; x < 4; ++x) {
        const Rgb over = count_color(counts.texels[x * 4], 0.0f, 4.0f);  // auto-fit: 0..max
        for (size_t c = 0; c < 3; ++c)
            EXPECT_EQ(pixel(view, x)[c], expected_blend(final_rgb[x][c], over[c], opacity))
                << "texel " << x << " channel " << c;
    }
}

// Two overlays stack in list order: the second blends over the first's result, so swapping
// them changes the pixel where both counted.
TEST(Overlays, SeveralOverlaysBlendInOrder) {
    const std::vector<Rgb> final_rgb{{40, 80, 120}, {40, 80, 120}, {40, 80, 120}};
    const InspectedImage a = scalar_row(Semantic::Count, VK_FORMAT_R32_UINT, {1.0f, 0.0f, 3.0f});
    const InspectedImage b = scalar_row(Semantic::Count, VK_FORMAT_R32_UINT, {0.0f, 5.0f, 1.0f});
    const DecodedView heat_a = decode(a, manual(0.0f, 5.0f)),
                      heat_b = decode(b, manual(0.0f, 5.0f));
    DecodedView ab = colours(final_rgb), ba = colours(final_rgb);
    ASSERT_TRUE(blend_overlay(ab, heat_a, a, 0.5f));
    ASSERT_TRUE(blend_overlay(ab, heat_b, b, 0.75f));
    ASSERT_TRUE(blend_overlay(ba, heat_b, b, 0.75f));
    ASSERT_TRUE(blend_overlay(ba, heat_a, a, 0.5f));
    const Rgb a0 = count_color(1, 0, 5), b1 = count_color(5, 0, 5);
    const Rgb a2 = count_color(3, 0, 5), b2 = count_color(1, 0, 5);
    for (size_t c = 0; c < 3; ++c) {
        EXPECT_EQ(pixel(ab, 0)[c], expected_blend(final_rgb[0][c], a0[c], 0.5));   // a only
        EXPECT_EQ(pixel(ab, 1)[c], expected_blend(final_rgb[1][c], b1[c], 0.75));  // b only
        const uint8_t under = expected_blend(final_rgb[2][c], a2[c], 0.5);
        EXPECT_NEAR(pixel(ab, 2)[c], expected_blend(under, b2[c], 0.75), 1) << c;
    }
    EXPECT_EQ(pixel(ab, 0), pixel(ba, 0));
    EXPECT_NE(pixel(ab, 2), pixel(ba, 2)) << "order matters where both counted";
    // Opacity 0 leaves the base, 1 replaces it; an image of another size changes nothing.
    DecodedView none = colours(final_rgb), full = colours(final_rgb);
    blend_overlay(none, heat_a, a, 0.0f);
    blend_overlay(full, heat_a, a, 1.0f);
    EXPECT_EQ(pixel(none, 2), final_rgb[2]);
    EXPECT_EQ(pixel(full, 2), a2);
    const InspectedImage wide = scalar_row(Semantic::Count, VK_FORMAT_R32_UINT, {1, 1, 1, 1});
    DecodedView same = colours(final_rgb);
    EXPECT_FALSE(blend_overlay(same, decode(wide, ViewParams{}), wide, 0.5f));
    EXPECT_EQ(same.rgba8, colours(final_rgb).rgba8);
}

// Wasted = max(shaded - covered, 0), covered where the depth is not far, in both conventions.
TEST(Wasted, ShadedMinusCoveredPerPixel) {
    InspectedImage shaded =
        scalar_row(Semantic::Count, VK_FORMAT_R32_UINT, {0.0f, 1.0f, 3.0f, 2.0f, 1.0f});
    shaded.name = "forward_counts";
    for (const Semantic convention : {Semantic::ReverseZDepth, Semantic::ForwardZDepth}) {
        const bool reverse = convention == Semantic::ReverseZDepth;
        const float far = reverse ? 0.0f : 1.0f;
        const float near2 = reverse ? reverse_z_stored(2.0f) : forward_z_stored(2.0f);
        InspectedImage depth =
            scalar_row(convention, VK_FORMAT_D32_SFLOAT, {far, near2, near2, far, near2});
        depth.name = "depth";
        const auto wasted = wasted_image(shaded, depth);
        ASSERT_TRUE(wasted);
        EXPECT_EQ(wasted->name, "forward_wasted");
        EXPECT_EQ(wasted->semantic, Semantic::Count);
        const std::vector<float> expected{0.0f, 0.0f, 2.0f, 2.0f, 0.0f};
        for (uint32_t x = 0; x < 5; ++x) EXPECT_EQ(wasted->texels[x * 4], expected[x]) << x;
    }
    // Only a pass's shaded counts and a perspective depth of the same size make one.
    InspectedImage discarded = shaded;
    discarded.name = "forward_discarded";
    const InspectedImage depth =
        scalar_row(Semantic::ReverseZDepth, VK_FORMAT_D32_SFLOAT, {0.0f, 0.5f, 0.5f, 0.0f, 0.5f});
    EXPECT_FALSE(wasted_image(discarded, depth));
    EXPECT_FALSE(
        wasted_image(shaded, scalar_row(Semantic::ReverseZDepth, VK_FORMAT_D32_SFLOAT, {0.0f})));
}

// The shared scale's top is the largest count over the pass's images, whatever order.
TEST(CountImages, TheSharedScaleIsTheMaxOverTheImages) {
    const InspectedImage a = scalar_row(Semantic::Count, VK_FORMAT_R32_UINT, {1, 7, 2});
    const InspectedImage b = scalar_row(Semantic::Count, VK_FORMAT_R32_UINT, {9, 0, 3});
    const InspectedImage* both[] = {&a, &b};
    const InspectedImage* first[] = {&a};
    EXPECT_EQ(count_max(both), 9.0f);
    EXPECT_EQ(count_max(first), 7.0f);
    EXPECT_EQ(count_max({}), 0.0f);
}

}  // namespace
}  // namespace ds::view::test
