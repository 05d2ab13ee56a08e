// DEPTHSCOPE_DEVICE_LIMITS parsing (pure): it only lowers, and anything else is an error.
#include <gtest/gtest.h>

#include "renderer/common/error.h"
#include "renderer/vk/device_limits.h"

namespace {

using ds::vk::DeviceLimits;

DeviceLimits lavapipe_like() {
    DeviceLimits l;
    l.max_image_dimension_2d = 16384;
    l.max_framebuffer_width = 16384;
    l.max_framebuffer_height = 16384;
    l.max_memory_allocation_size = 2ull << 30;
    l.heap_index = 0;
    l.heap_bytes = 2ull << 30;
    return l;
}

TEST(DeviceLimits, OverridesLowerTheNamedLimits) {
    DeviceLimits l = lavapipe_like();
    ds::vk::apply_limit_overrides(l, "image=512, heap_mib=64 allocation_mib=16");
    EXPECT_EQ(l.max_image_dimension_2d, 512u);
    EXPECT_EQ(l.max_framebuffer_width, 512u);
    EXPECT_EQ(l.max_framebuffer_height, 512u);
    EXPECT_EQ(l.heap_bytes, 64ull << 20);
    EXPECT_EQ(l.max_memory_allocation_size, 16ull << 20);
    EXPECT_TRUE(l.lowered);
}

TEST(DeviceLimits, OverridesNeverRaise) {
    DeviceLimits l = lavapipe_like();
    ds::vk::apply_limit_overrides(l, "image=100000 heap_mib=1000000");
    EXPECT_EQ(l.max_image_dimension_2d, 16384u);
    EXPECT_EQ(l.heap_bytes, 2ull << 30);
    EXPECT_FALSE(l.lowered);
}

TEST(DeviceLimits, BadOverridesAreErrors) {
    for (const char* text : {"image", "image=", "image=0", "image=-4", "image=12abc", "gpu=4",
                             "heap_mib=99999999999999"}) {
        DeviceLimits l = lavapipe_like();
        EXPECT_THROW(ds::vk::apply_limit_overrides(l, text), ds::Error) << text;
    }
}

TEST(DeviceLimits, BytesText) {
    EXPECT_EQ(ds::vk::bytes_text(512), "512 B");
    EXPECT_EQ(ds::vk::bytes_text(64ull << 20), "64.0 MiB");
    EXPECT_EQ(ds::vk::bytes_text(11ull << 30 | 512ull << 20), "11.5 GiB");
}

}  // namespace
