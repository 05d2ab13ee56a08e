#pragma once
// Sub-allocation of large VkDeviceMemory blocks, as pure bookkeeping over offsets (no Vulkan
// calls) so it is unit-tested directly. The Vulkan side (memory.h) maps blocks to memory.
//
// bufferImageGranularity: the Vulkan allocator keeps linear resources (buffers) and optimal
// images in separate pools, so neighbours in a block never mix the two kinds and no
// granularity padding is needed here.
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace ds::vk {

constexpr uint64_t align_up(uint64_t value, uint64_t alignment) {
    return alignment <= 1 ? value : (value + alignment - 1) / alignment * alignment;
}

// One block's address space: first fit over an ordered free list; neighbours coalesce on free.
class BlockAllocator {
  public:
    explicit BlockAllocator(uint64_t size);

    // Offset of `size` bytes aligned to `alignment` (any positive value), or nullopt when no
    // free range fits. Size 0 is treated as 1 so every allocation has a distinct offset.
    std::optional<uint64_t> allocate(uint64_t size, uint64_t alignment);
    // Frees the allocation that starts at `offset`; throws std::logic_error for an unknown one.
    void free(uint64_t offset);

    uint64_t size() const { return size_; }
    uint64_t used() const { return used_; }
    bool empty() const { return allocated_.empty(); }
    size_t allocation_count() const { return allocated_.size(); }
    size_t free_range_count() const { return free_.size(); }
    uint64_t largest_free_range() const;

  private:
    uint64_t size_;
    uint64_t used_ = 0;
    std::map<uint64_t, uint64_t> free_;       // offset -> size; never adjacent (coalesced)
    std::map<uint64_t, uint64_t> allocated_;  // offset -> size
};

struct SubAllocation {
    uint32_t block = 0;
    uint64_t offset = 0;
    uint64_t size = 0;
};

// Blocks of one size for one (memory type, resource kind); grows by explicit add_block() so
// the caller can create the backing memory first and stay consistent when that fails.
class BlockPool {
  public:
    explicit BlockPool(uint64_t block_size) : block_size_(block_size) {}

    std::optional<SubAllocation> try_allocate(uint64_t size, uint64_t alignment);
    uint32_t add_block();  // index of the new, empty block
    void free(const SubAllocation& allocation);

    uint64_t block_size() const { return block_size_; }
    size_t block_count() const { return blocks_.size(); }
    const BlockAllocator& block(uint32_t index) const { return blocks_.at(index); }

  private:
    uint64_t block_size_;
    std::vector<BlockAllocator> blocks_;
};

}  // namespace ds::vk
