// Block sub-allocator bookkeeping: alignment, reuse, coalescing, growth.
#include <gtest/gtest.h>

#include "renderer/vk/block_allocator.h"

namespace {

using ds::vk::BlockAllocator;
using ds::vk::BlockPool;

TEST(BlockAllocator, AlignsOffsets) {
    BlockAllocator block(1024);
    EXPECT_EQ(block.allocate(10, 1), 0u);
    EXPECT_EQ(block.allocate(16, 64), 64u);  // 10 rounded up to the next multiple of 64
    EXPECT_EQ(block.allocate(4, 256), 256u);
    EXPECT_EQ(block.allocate(1, 3), 12u);  // non-power-of-two alignments work too; gap reused
    EXPECT_EQ(block.used(), 10u + 16u + 4u + 1u);
}

TEST(BlockAllocator, AlignmentGapStaysUsable) {
    BlockAllocator block(256);
    ASSERT_EQ(block.allocate(8, 1), 0u);
    ASSERT_EQ(block.allocate(8, 128), 128u);
    EXPECT_EQ(block.allocate(100, 1), 8u);  // fits in the 8..128 gap left by alignment
}

TEST(BlockAllocator, ReusesFreedRange) {
    BlockAllocator block(300);
    const auto a = block.allocate(100, 4);
    const auto b = block.allocate(100, 4);
    ASSERT_TRUE(a && b);
    block.free(*a);
    EXPECT_EQ(block.allocate(100, 4), a);  // first fit finds the hole again
    EXPECT_EQ(block.allocate(100, 4), 200u);
    EXPECT_FALSE(block.allocate(1, 1).has_value());
}

TEST(BlockAllocator, CoalescesNeighboursOnFree) {
    BlockAllocator block(400);
    auto a = *block.allocate(100, 1), b = *block.allocate(100, 1);
    auto c = *block.allocate(100, 1), d = *block.allocate(100, 1);
    EXPECT_EQ(block.free_range_count(), 0u);
    block.free(a);
    block.free(c);
    EXPECT_EQ(block.free_range_count(), 2u);
    EXPECT_FALSE(block.allocate(200, 1).has_value());  // fragmented: no 200-byte hole
    block.free(b);                                     // merges with a (left) and c (right)
    EXPECT_EQ(block.free_range_count(), 1u);
    EXPECT_EQ(block.largest_free_range(), 300u);
    EXPECT_EQ(block.allocate(300, 1), 0u);
    block.free(0);
    block.free(d);
    EXPECT_TRUE(block.empty());
    EXPECT_EQ(block.free_range_count(), 1u);
    EXPECT_EQ(block.largest_free_range(), 400u);
}

TEST(BlockAllocator, ZeroSizeAllocationsAreDistinct) {
    BlockAllocator block(16);
    auto a = block.allocate(0, 1), b = block.allocate(0, 1);
    ASSERT_TRUE(a && b);
    EXPECT_NE(*a, *b);
}

TEST(BlockAllocator, UnknownFreeThrows) {
    BlockAllocator block(64);
    block.allocate(8, 1);
    EXPECT_THROW(block.free(4), std::logic_error);
}

TEST(BlockPool, OutOfSpaceNeedsANewBlock) {
    BlockPool pool(1024);
    EXPECT_FALSE(pool.try_allocate(16, 16).has_value());  // no blocks yet
    EXPECT_EQ(pool.add_block(), 0u);
    auto a = pool.try_allocate(1000, 16);
    ASSERT_TRUE(a);
    EXPECT_EQ(a->block, 0u);
    EXPECT_FALSE(pool.try_allocate(64, 16).has_value());  // 24 bytes left in block 0
    EXPECT_EQ(pool.add_block(), 1u);
    auto b = pool.try_allocate(64, 16);
    ASSERT_TRUE(b);
    EXPECT_EQ(b->block, 1u);
    EXPECT_EQ(b->offset, 0u);
    auto c = pool.try_allocate(16, 8);  // small ones still fill block 0 first
    ASSERT_TRUE(c);
    EXPECT_EQ(c->block, 0u);
    EXPECT_EQ(c->offset, 1000u);
    pool.free(*a);
    auto d = pool.try_allocate(512, 256);
    ASSERT_TRUE(d);
    EXPECT_EQ(d->block, 0u);
    EXPECT_EQ(d->offset, 0u);
    EXPECT_EQ(pool.block_count(), 2u);
}

}  // namespace
