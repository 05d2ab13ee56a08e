// Mip chain sizes (the CPU box filter is scene/alpha_mips.h's: tests/unit/scene).
#include <gtest/gtest.h>

#include "renderer/vk/image.h"

namespace {

TEST(Mips, LevelCountCoversTheFullChain) {
    EXPECT_EQ(ds::vk::mip_level_count(1, 1), 1u);
    EXPECT_EQ(ds::vk::mip_level_count(2, 1), 2u);
    EXPECT_EQ(ds::vk::mip_level_count(64, 64), 7u);
    EXPECT_EQ(ds::vk::mip_level_count(100, 30), 7u);  // 100 50 25 12 6 3 1
}

}  // namespace
