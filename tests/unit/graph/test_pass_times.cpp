// pass_times(): each pass's start and GPU time from its two ticks, the device's valid bits
// masked, as the profiler computes gpu_ms and gpu_start_ms. No device needed.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "renderer/graph/profiler.h"

namespace ds::graph {
namespace {

TEST(PassTimes, StartsAfterTheFirstTickAndLastsFromBeginToEnd) {
    // Three passes, 2 ns a tick: [100, 160], [160, 400], [450, 451].
    const std::vector<uint64_t> ticks = {100, 160, 160, 400, 450, 451};
    const std::vector<PassTime> t = pass_times(ticks, 64, 2.0);
    ASSERT_EQ(t.size(), 3u);
    EXPECT_EQ(t[0].start_ms, 0.0);
    EXPECT_DOUBLE_EQ(t[0].gpu_ms, 120e-6);
    EXPECT_DOUBLE_EQ(t[1].start_ms, 120e-6);
    EXPECT_DOUBLE_EQ(t[1].gpu_ms, 480e-6);
    EXPECT_DOUBLE_EQ(t[2].start_ms, 700e-6);
    EXPECT_DOUBLE_EQ(t[2].gpu_ms, 2e-6);
}

// A 36-bit counter that wraps during the frame: only the low bits are valid (the rest may be
// anything), and the distances are taken modulo 2^36.
TEST(PassTimes, ACounterThatWrapsStillGivesTheDistances) {
    const uint64_t wrap = 1ull << 36;
    const uint64_t junk = 0xabcull << 40;  // bits above the valid ones
    const std::vector<uint64_t> ticks = {junk | (wrap - 100), junk | (wrap - 40), 20, 70};
    const std::vector<PassTime> t = pass_times(ticks, 36, 1.0);
    ASSERT_EQ(t.size(), 2u);
    EXPECT_EQ(t[0].start_ms, 0.0);
    EXPECT_DOUBLE_EQ(t[0].gpu_ms, 60e-6);
    EXPECT_DOUBLE_EQ(t[1].start_ms, 120e-6);
    EXPECT_DOUBLE_EQ(t[1].gpu_ms, 50e-6);
}

TEST(PassTimes, NoPassesNoTimes) {
    EXPECT_TRUE(pass_times({}, 64, 1.0).empty());
}

}  // namespace
}  // namespace ds::graph
