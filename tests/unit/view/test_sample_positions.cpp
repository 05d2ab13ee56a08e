// The standard sample positions table (the sample view draws from it).
#include <gtest/gtest.h>

#include <set>

#include "renderer/view/sample_positions.h"

namespace ds::view {
namespace {

TEST(SamplePositions, FourSamplesAreTheSpecTable) {
    const auto p = standard_sample_positions(4);
    ASSERT_EQ(p.size(), 4u);
    const float want[4][2] = {
        {0.375f, 0.125f}, {0.875f, 0.375f}, {0.125f, 0.625f}, {0.625f, 0.875f}};
    for (size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(p[i].x, want[i][0]) << i;
        EXPECT_EQ(p[i].y, want[i][1]) << i;
    }
}

TEST(SamplePositions, OneSampleIsThePixelCentreAndTwoAreDiagonal) {
    ASSERT_EQ(standard_sample_positions(1).size(), 1u);
    EXPECT_EQ(standard_sample_positions(1)[0].x, 0.5f);
    EXPECT_EQ(standard_sample_positions(1)[0].y, 0.5f);
    const auto two = standard_sample_positions(2);
    ASSERT_EQ(two.size(), 2u);
    EXPECT_EQ(two[0].x, 0.75f);
    EXPECT_EQ(two[1].y, 0.25f);
}

// Every pattern of n > 1 samples lies on the n x n grid of sixteenths (or eighths) with one
// sample in each column and each row (no two share an x or a y), inside the pixel.
TEST(SamplePositions, EveryPatternIsInsideThePixelWithDistinctRowsAndColumns) {
    for (uint32_t n : {2u, 4u, 8u, 16u}) {
        const auto p = standard_sample_positions(n);
        ASSERT_EQ(p.size(), n);
        std::set<float> xs, ys;
        for (const SamplePosition& s : p) {
            EXPECT_GE(s.x, 0.0f);
            EXPECT_LT(s.x, 1.0f);
            EXPECT_GE(s.y, 0.0f);
            EXPECT_LT(s.y, 1.0f);
            EXPECT_EQ(s.x * 16.0f, float(int(s.x * 16.0f))) << n;  // on the 1/16 grid
            xs.insert(s.x);
            ys.insert(s.y);
        }
        EXPECT_EQ(xs.size(), n);
        EXPECT_EQ(ys.size(), n);
    }
}

TEST(SamplePositions, OtherCountsHaveNoTable) {
    EXPECT_TRUE(standard_sample_positions(0).empty());
    EXPECT_TRUE(standard_sample_positions(3).empty());
    EXPECT_TRUE(standard_sample_positions(32).empty());
}

}  // namespace
}  // namespace ds::view
