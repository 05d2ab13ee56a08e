// The host side of the layer's Z-fight and EQUAL checks (layer/depth_records.h): which
// fragment the attachment keeps under each compare op, the steps of each depth format, what
// fights, geometry matching, holes and ties.
#include <gtest/gtest.h>

#include <bit>

#include "layer/depth_records.h"

namespace ds::layer {
namespace {

uint32_t bits(float z) {
    return std::bit_cast<uint32_t>(z);
}

std::map<uint32_t, DepthUse> uses(VkCompareOp op, std::initializer_list<uint32_t> draws) {
    std::map<uint32_t, DepthUse> out;
    for (uint32_t d : draws) out[d] = {true, true, op};
    return out;
}

TEST(DepthRecords, EqualDepthsGoToTheFirstDrawUnderLessAndTheLastUnderLessOrEqual) {
    // One pixel, draws 3 and 7 at the same depth, and draw 9 one ULP behind.
    const float z = 0.5f;
    const DepthRecord records[] = {{0, 7, 0, bits(z)}, {0, 3, 0, bits(z)}, {0, 9, 2, bits(z) + 1}};
    const auto less = analyse_depth_pass(records, 1, 1, 32, 4, uses(VK_COMPARE_OP_LESS, {3, 7, 9}));
    EXPECT_EQ(less.winners[0], (DrawInstance{3, 0}));
    const auto lequal =
        analyse_depth_pass(records, 1, 1, 32, 4, uses(VK_COMPARE_OP_LESS_OR_EQUAL, {3, 7, 9}));
    EXPECT_EQ(lequal.winners[0], (DrawInstance{7, 0}));
    ASSERT_EQ(less.pairs.size(), 2u);  // the winner with each competitor, one pixel each
    EXPECT_EQ(less.competitors[0], 2u);
    EXPECT_EQ(less.pixels, 1u);
    EXPECT_EQ(less.pairs[0].pixels, 1u);
}

TEST(DepthRecords, ReverseDepthKeepsTheLargerValue) {
    const DepthRecord records[] = {{0, 1, 0, bits(0.25f)}, {0, 2, 0, bits(0.75f)}};
    const auto greater =
        analyse_depth_pass(records, 1, 1, 32, 4, uses(VK_COMPARE_OP_GREATER, {1, 2}));
    EXPECT_EQ(greater.winners[0], (DrawInstance{2, 0}));
    EXPECT_TRUE(greater.pairs.empty());  // far apart
}

TEST(DepthRecords, StepsAreThoseOfTheAttachmentFormat) {
    // Two surfaces 3 D16 steps apart: a fight at zfight_steps 4 in D16, not at 2; in D32 the
    // same gap is about 770 ULPs.
    const float a = 0.5f, b = a + 3.0f / 65535.0f;
    const DepthRecord records[] = {{0, 1, 0, bits(a)}, {0, 2, 0, bits(b)}};
    const auto u = uses(VK_COMPARE_OP_LESS, {1, 2});
    EXPECT_EQ(analyse_depth_pass(records, 1, 1, 16, 4, u).pairs.size(), 1u);
    EXPECT_EQ(analyse_depth_pass(records, 1, 1, 16, 4, u).pairs[0].min_steps, 3u);
    EXPECT_TRUE(analyse_depth_pass(records, 1, 1, 16, 2, u).pairs.empty());
    EXPECT_TRUE(analyse_depth_pass(records, 1, 1, 32, 512, u).pairs.empty());
    EXPECT_EQ(analyse_depth_pass(records, 1, 1, 32, 1024, u).pairs.size(), 1u);
    EXPECT_EQ(depth_steps_value(16, bits(1.0f)), 65535u);
    EXPECT_EQ(depth_steps_value(16, bits(0.0f)), 0u);
    EXPECT_EQ(depth_steps_value(24, bits(0.5f)), 8388608u);  // 0.5 * (2^24 - 1) + 0.5, in float
}

TEST(DepthRecords, ADrawAndInstanceNeverFightsItselfButOtherInstancesDo) {
    const DepthRecord records[] = {
        {5, 1, 0, bits(0.5f)}, {5, 1, 0, bits(0.5f)}, {5, 1, 1, bits(0.5f)}, {6, 1, 0, bits(0.5f)}};
    const auto r = analyse_depth_pass(records, 4, 2, 32, 0, uses(VK_COMPARE_OP_LESS, {1}));
    ASSERT_EQ(r.pairs.size(), 1u);
    EXPECT_EQ(r.pairs[0].a, (DrawInstance{1, 0}));
    EXPECT_EQ(r.pairs[0].b, (DrawInstance{1, 1}));
    EXPECT_EQ(r.competitors[5], 1u);
    EXPECT_EQ(r.competitors[6], 0u);
    EXPECT_EQ(r.winners[7].draw, UINT32_MAX);
}

TEST(DepthRecords, GeometryMatchesByBuffersAndRangesWhateverTheInstances) {
    DrawGeometry a;
    a.indexed = true;
    a.index_buffer = reinterpret_cast<VkBuffer>(uintptr_t(0x10));
    a.args = {DrawKind::Indexed, 36, 6, 12, 0, 0};
    a.vertex[0] = {reinterpret_cast<VkBuffer>(uintptr_t(0x20)), 0};
    DrawGeometry b = a;
    b.args.instances = 1;
    b.args.first_instance = 3;
    b.vertex[1] = {reinterpret_cast<VkBuffer>(uintptr_t(0x30)), 64};  // read by b only
    EXPECT_TRUE(same_geometry(a, b));
    b.args.first = 48;
    EXPECT_FALSE(same_geometry(a, b));
    b = a;
    b.vertex[0].second = 16;
    EXPECT_FALSE(same_geometry(a, b));
    b = a;
    b.index_offset = 4;
    EXPECT_FALSE(same_geometry(a, b));
}

TEST(DepthRecords, EqualCheckMarksHolesOfMatchedWinnersAndTies) {
    // 3 x 1 pixels: prepass winners draw 4 (matched), draw 5 (not matched), none.
    const PrepassWinners prepass{2, 3, 1, {{4, 0}, {5, 0}, {UINT32_MAX, 0}}};
    const uint32_t words[] = {0, 0, 0, 0, 0, 2};  // nearest, survivors per pixel
    const EqualCheckResult r = equal_check(words, 3, 1, prepass, {4});
    EXPECT_EQ(r.holes, 1u);  // pixel 0; pixel 1's winner is not drawn again
    EXPECT_EQ(r.multiple, 1u);
    EXPECT_EQ(r.marks, (std::vector<uint32_t>{1, 0, 2}));
    EXPECT_EQ(r.prepass, 2u);
    EXPECT_EQ(r.by_winner.at(DrawInstance{4, 0}).first, 1u);
}

}  // namespace
}  // namespace ds::layer
