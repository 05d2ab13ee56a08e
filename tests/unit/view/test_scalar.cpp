// Scalar images (issue 23): decoded, read out and given a legend only from their
// graph::Display (scale, range rule, palette, unit, hover text), against colours worked out
// by hand from the heat map's stops (heat.cpp: t = 0.25 -> (0, 217, 200), 0.5 -> (130, 220,
// 20), 0.75 -> (240, 74, 0), 1 -> white, the first colour above black (0, 40, 255)).
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "renderer/view/decode.h"
#include "renderer/view/heat.h"
#include "renderer/view/readout.h"
#include "tests/unit/view/view_test_images.h"

namespace {

using ds::InspectedImage;
using ds::graph::Display;
using ds::graph::DisplayRange;
using ds::graph::Palette;
using ds::graph::Semantic;
using ds::graph::ValueScale;
using ds::view::DecodedView;
using ds::view::ViewParams;
using namespace ds::view::test;  // Rgb, scalar_row, pixel, manual

constexpr Rgb kBlack{0, 0, 0}, kWhite{255, 255, 255};
constexpr Rgb kFirst{0, 40, 255};  // the heat map just above black
constexpr Rgb kHeatQuarter{0, 217, 200}, kHeatHalf{130, 220, 20}, kHeatThreeQuarters{240, 74, 0};
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

InspectedImage scalar(const Display& display, const std::vector<float>& values) {
    InspectedImage image = scalar_row(Semantic::Scalar, VK_FORMAT_R32_SFLOAT, values);
    image.display = display;
    return image;
}

Display log_heat(DisplayRange range) {
    return {.scale = ValueScale::Log, .range = range, .palette = Palette::Heat, .unit = "px²"};
}

// MinMax over log10: 0.01..100 is -2..2, so 0.1 is a quarter and 10 three quarters; the
// smallest value keeps the first colour (only "no value" is black); 0 and below are black.
TEST(DecodeScalar, LogHeatMinMax) {
    const InspectedImage image =
        scalar(log_heat(DisplayRange::min_max()), {0.01f, 0.1f, 10.0f, 100.0f, 0.0f, -1.0f, kNaN});
    const DecodedView view = ds::view::decode(image, ViewParams{});
    ASSERT_EQ(view.width, 7u);
    EXPECT_FLOAT_EQ(view.black, 0.01f);  // in the value's unit, as read
    EXPECT_FLOAT_EQ(view.white, 100.0f);
    EXPECT_EQ(view.unit, "px²");
    EXPECT_EQ(pixel(view, 0), kFirst);
    EXPECT_EQ(pixel(view, 1), kHeatQuarter);
    EXPECT_EQ(pixel(view, 2), kHeatThreeQuarters);
    EXPECT_EQ(pixel(view, 3), kWhite);
    EXPECT_EQ(pixel(view, 4), kBlack);
    EXPECT_EQ(pixel(view, 5), kBlack);
    const auto magenta = ds::view::kNonFiniteColor;
    EXPECT_EQ(pixel(view, 6), (Rgb{magenta[0], magenta[1], magenta[2]}));
}

// ZeroToMax on a log scale: log10 v from 0, so the values 1..max; below 1 the first colour.
TEST(DecodeScalar, LogHeatZeroToMax) {
    const InspectedImage image =
        scalar(log_heat(DisplayRange::zero_to_max()), {0.5f, 1.0f, 10.0f, 100.0f, 0.0f});
    const DecodedView view = ds::view::decode(image, ViewParams{});
    EXPECT_FLOAT_EQ(view.black, 1.0f);
    EXPECT_FLOAT_EQ(view.white, 100.0f);
    EXPECT_EQ(pixel(view, 0), kFirst);
    EXPECT_EQ(pixel(view, 1), kFirst);
    EXPECT_EQ(pixel(view, 2), kHeatHalf);
    EXPECT_EQ(pixel(view, 3), kWhite);
    EXPECT_EQ(pixel(view, 4), kBlack);
}

// Linear heat from zero is the count heat map: the same bytes as a Count image of the values.
TEST(DecodeScalar, LinearHeatZeroToMaxIsTheCountHeatMap) {
    const std::vector<float> values{0.0f, 1.0f, 2.0f, 3.0f, 4.0f};
    const Display display{.range = DisplayRange::zero_to_max(), .palette = Palette::Heat};
    const DecodedView view = ds::view::decode(scalar(display, values), ViewParams{});
    EXPECT_EQ(view.black, 0.0f);
    EXPECT_EQ(view.white, 4.0f);
    EXPECT_EQ(view.unit, "");
    EXPECT_EQ(pixel(view, 0), kBlack);
    EXPECT_EQ(pixel(view, 1), kHeatQuarter);
    EXPECT_EQ(pixel(view, 2), kHeatHalf);
    EXPECT_EQ(pixel(view, 3), kHeatThreeQuarters);
    EXPECT_EQ(pixel(view, 4), kWhite);
    const InspectedImage counts = scalar_row(Semantic::Count, VK_FORMAT_R32_UINT, values);
    EXPECT_EQ(view.rgba8, ds::view::decode(counts, ViewParams{}).rgba8);
}

// A fixed range, in the value's unit, on either scale; the viewer's manual range wins.
TEST(DecodeScalar, FixedRange) {
    const Display linear{.range = DisplayRange::fixed(10.0f, 20.0f), .unit = "ms"};
    const DecodedView grey =
        ds::view::decode(scalar(linear, {5.0f, 10.0f, 15.0f, 20.0f, 25.0f}), ViewParams{});
    EXPECT_EQ(grey.black, 10.0f);
    EXPECT_EQ(grey.white, 20.0f);
    EXPECT_EQ(grey.unit, "ms");
    EXPECT_EQ(pixel(grey, 0), kBlack);
    EXPECT_EQ(pixel(grey, 1), kBlack);
    EXPECT_EQ(pixel(grey, 2), (Rgb{128, 128, 128}));
    EXPECT_EQ(pixel(grey, 3), kWhite);
    EXPECT_EQ(pixel(grey, 4), kWhite);

    const InspectedImage logged = scalar(
        {.scale = ValueScale::Log, .range = DisplayRange::fixed(1.0f, 100.0f)}, {1.0f, 10.0f});
    const DecodedView log_grey = ds::view::decode(logged, ViewParams{});
    EXPECT_EQ(log_grey.black, 1.0f);
    EXPECT_EQ(log_grey.white, 100.0f);
    EXPECT_EQ(pixel(log_grey, 0), kBlack);
    EXPECT_EQ(pixel(log_grey, 1), (Rgb{128, 128, 128}));  // a decade of two

    const DecodedView overridden = ds::view::decode(logged, manual(10.0f, 1000.0f));
    EXPECT_EQ(overridden.black, 10.0f);
    EXPECT_EQ(pixel(overridden, 1), kBlack);
}

// One value: mid palette; no value to fit: 0..1 of the shown quantity (log: 1..10).
TEST(DecodeScalar, FlatAndEmptyImages) {
    const DecodedView flat =
        ds::view::decode(scalar(log_heat(DisplayRange::min_max()), {5.0f, 5.0f}), ViewParams{});
    EXPECT_EQ(flat.black, 5.0f);
    EXPECT_EQ(flat.white, 5.0f);
    EXPECT_EQ(pixel(flat, 0), ds::view::heat_color(0.5f));
    const DecodedView empty =
        ds::view::decode(scalar(log_heat(DisplayRange::min_max()), {0.0f, kNaN}), ViewParams{});
    EXPECT_EQ(empty.black, 1.0f);
    EXPECT_EQ(empty.white, 10.0f);
    const DecodedView linear = ds::view::decode(scalar({}, {kNaN}), ViewParams{});
    EXPECT_EQ(linear.black, 0.0f);
    EXPECT_EQ(linear.white, 1.0f);
}

// The colour bar's stops are the colours decode gives their values.
TEST(DecodeScalar, LegendMatchesTheColours) {
    const Display display = log_heat(DisplayRange::min_max());
    const InspectedImage image = scalar(display, {0.01f, 0.1f, 10.0f, 100.0f});
    const DecodedView view = ds::view::decode(image, ViewParams{});
    const auto stops = ds::view::display_legend(display, view.black, view.white, 5);
    ASSERT_EQ(stops.size(), 5u);
    EXPECT_NEAR(stops[0].count, 0.01f, 1e-6f);
    EXPECT_NEAR(stops[1].count, 0.1f, 1e-5f);
    EXPECT_NEAR(stops[4].count, 100.0f, 1e-3f);
    EXPECT_EQ(stops[0].rgb, pixel(view, 0));
    EXPECT_EQ(stops[1].rgb, pixel(view, 1));
    EXPECT_EQ(stops[3].rgb, pixel(view, 2));
    EXPECT_EQ(stops[4].rgb, pixel(view, 3));
    EXPECT_EQ(ds::view::display_legend(display, 5.0f, 5.0f).size(), 1u);
    EXPECT_TRUE(ds::view::display_legend(display, 5.0f, 1.0f).empty());
}

// Hover: the Display's format with the value at 3 significant digits.
TEST(Readout, ScalarHoverTextFromItsDisplay) {
    const Display display{.unit = "px²", .hover = "triangle {} px²"};
    const auto r = ds::view::readout(scalar(display, {0.18f, 1234.5f}), 0, 0);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->decoded_text, "triangle 0.18 px²");
    EXPECT_EQ(r->raw_text, "0.18");
    EXPECT_EQ(ds::view::readout(scalar(display, {0.18f, 1234.5f}), 1, 0)->decoded_text,
              "triangle 1230 px²");
    EXPECT_EQ(ds::view::readout(scalar({}, {2.0f}), 0, 0)->decoded_text, "2");  // "{}"
    EXPECT_EQ(ds::view::hover_text("{} of {}", 3.0f), "3 of 3");
    EXPECT_EQ(ds::view::hover_text("no value", 3.0f), "no value");
}

TEST(Readout, ValueTextHasThreeSignificantDigits) {
    EXPECT_EQ(ds::view::value_text(0.18f), "0.18");
    EXPECT_EQ(ds::view::value_text(0.123456f), "0.123");
    EXPECT_EQ(ds::view::value_text(0.000123456f), "0.000123");
    EXPECT_EQ(ds::view::value_text(0.0000123f), "1.23e-05");
    EXPECT_EQ(ds::view::value_text(0.0f), "0");
    EXPECT_EQ(ds::view::value_text(2.0f), "2");
    EXPECT_EQ(ds::view::value_text(99.96f), "100");
    EXPECT_EQ(ds::view::value_text(999.7f), "1000");
    EXPECT_EQ(ds::view::value_text(-1234.5f), "-1230");
    EXPECT_EQ(ds::view::value_text(456789.0f), "457000");
    EXPECT_EQ(ds::view::value_text(1.5e7f), "1.5e+07");
    EXPECT_EQ(ds::view::value_text(std::numeric_limits<float>::infinity()), "inf");
}

}  // namespace
