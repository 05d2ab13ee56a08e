// Luma, the per-pixel error map, edge error and the pixels over a threshold
// (renderer/metrics) on hand-made images.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "renderer/common/error.h"
#include "renderer/metrics/luma.h"
#include "renderer/metrics/threshold.h"

namespace ds::metrics {
namespace {

std::vector<uint8_t> grey_bytes(size_t pixels, uint8_t v) {
    return std::vector<uint8_t>(pixels * 4, v);
}

TEST(Luma, Rec709WeightsOnTheCodes) {
    const std::vector<uint8_t> bytes{255, 0,   0,   255, 0,  255, 0,  0,   0, 0, 255, 9,
                                     255, 255, 255, 0,   10, 20,  30, 255, 0, 0, 0,   255};
    const LumaImage y = luma({3, 2, bytes});
    ASSERT_EQ(y.values.size(), 6u);
    EXPECT_DOUBLE_EQ(y.at(0, 0), 0.2126 * 255);
    EXPECT_DOUBLE_EQ(y.at(1, 0), 0.7152 * 255);  // alpha ignored
    EXPECT_DOUBLE_EQ(y.at(2, 0), 0.0722 * 255);
    EXPECT_DOUBLE_EQ(y.at(0, 1), 255.0);  // no linearisation: white is 255
    EXPECT_DOUBLE_EQ(y.at(1, 1), 0.2126 * 10 + 0.7152 * 20 + 0.0722 * 30);
    EXPECT_EQ(y.at(2, 1), 0.0);
    EXPECT_THROW(luma({3, 3, bytes}), Error);
}

TEST(LumaError, AbsoluteDifferenceMap) {
    const LumaImage a{2, 1, {10.0, 3.5}}, b{2, 1, {4.0, 5.0}};
    const LumaImage d = abs_difference(a, b);
    EXPECT_EQ(d.width, 2u);
    EXPECT_EQ(d.values, (std::vector<double>{6.0, 1.5}));
    EXPECT_THROW(abs_difference(a, LumaImage{1, 2, {0, 0}}), Error);
}

TEST(LumaError, EdgeErrorAveragesOverTheMask) {
    const LumaImage a{3, 2, {0, 10, 20, 30, 40, 50}}, b{3, 2, {1, 10, 26, 30, 40, 40}};
    const MaskedError e = edge_error(a, b, {true, true, true, false, false, true});
    EXPECT_EQ(e.pixels, 4u);
    EXPECT_DOUBLE_EQ(e.mean, (1.0 + 0.0 + 6.0 + 10.0) / 4);
    // Nothing selected: no pixels, and no mean to give.
    const MaskedError none = edge_error(a, b, std::vector<bool>(6, false));
    EXPECT_EQ(none.pixels, 0u);
    EXPECT_TRUE(std::isnan(none.mean));
    EXPECT_THROW(edge_error(a, b, std::vector<bool>(5, true)), Error);
}

// depthscope diff's final.png rule: a pixel counts when any channel (alpha too) differs by at
// least the threshold.
TEST(OverThreshold, LargestChannelDifferenceAgainstTheThreshold) {
    const std::vector<uint8_t> a = grey_bytes(4, 100);
    std::vector<uint8_t> b = a;
    b[0 * 4 + 0] = 107;  // R by 7: below 8
    b[1 * 4 + 1] = 92;   // G by 8: over
    b[2 * 4 + 3] = 0;    // A by 100: over
    const Rgba8View va{4, 1, a}, vb{4, 1, b};
    EXPECT_EQ(largest_channel_differences(va, vb), (std::vector<uint8_t>{7, 8, 100, 0}));
    const OverThreshold at8 = pixels_over_threshold(va, vb, 8);
    EXPECT_EQ(at8.over, 2u);
    EXPECT_EQ(at8.pixels, 4u);
    EXPECT_DOUBLE_EQ(at8.percent(), 50.0);
    EXPECT_EQ(pixels_over_threshold(va, vb, 1).over, 3u);
    EXPECT_EQ(pixels_over_threshold(va, vb, 0).over, 3u);  // a pixel that is equal never counts
    EXPECT_EQ(pixels_over_threshold(va, vb, 101).over, 0u);
    EXPECT_EQ(pixels_over_threshold(va, va, 1).over, 0u);
    EXPECT_EQ(OverThreshold{}.percent(), 0.0);
    EXPECT_THROW(pixels_over_threshold(va, {2, 2, b}, 8), Error);
    EXPECT_THROW(pixels_over_threshold(va, {4, 1, grey_bytes(3, 0)}, 8), Error);
}

}  // namespace
}  // namespace ds::metrics
