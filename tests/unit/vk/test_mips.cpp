// CPU mip fallback (used when a format cannot be blitted with a linear filter).
#include <gtest/gtest.h>

#include "renderer/vk/image.h"
#include "renderer/vk/upload.h"

namespace {

TEST(Mips, LevelCountCoversTheFullChain) {
    EXPECT_EQ(ds::vk::mip_level_count(1, 1), 1u);
    EXPECT_EQ(ds::vk::mip_level_count(2, 1), 2u);
    EXPECT_EQ(ds::vk::mip_level_count(64, 64), 7u);
    EXPECT_EQ(ds::vk::mip_level_count(100, 30), 7u);  // 100 50 25 12 6 3 1
}

TEST(Mips, BoxFilterAveragesTwoByTwo) {
    const uint8_t src[2 * 2 * 4] = {0, 10, 100, 255, 4,  10, 100, 255,
                                    8, 10, 100, 255, 12, 10, 100, 0};
    const std::vector<uint8_t> out = ds::vk::downsample_rgba8(src, 2, 2);
    ASSERT_EQ(out.size(), 4u);
    EXPECT_EQ(out[0], 6);  // (0 + 4 + 8 + 12 + 2) / 4, rounded
    EXPECT_EQ(out[1], 10);
    EXPECT_EQ(out[2], 100);
    EXPECT_EQ(out[3], 191);  // (3 * 255 + 0 + 2) / 4
}

TEST(Mips, OddSizesClampAndNeverReachZero) {
    std::vector<uint8_t> src(3 * 1 * 4, 200);
    const std::vector<uint8_t> out = ds::vk::downsample_rgba8(src.data(), 3, 1);
    EXPECT_EQ(out.size(), 1u * 1u * 4u);
    EXPECT_EQ(out[0], 200);
}

}  // namespace
