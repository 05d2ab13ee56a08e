#include "renderer/vk/block_allocator.h"

#include <algorithm>
#include <stdexcept>

namespace ds::vk {

BlockAllocator::BlockAllocator(uint64_t size) : size_(size) {
    if (size > 0) free_.emplace(0, size);
}

std::optional<uint64_t> BlockAllocator::allocate(uint64_t size, uint64_t alignment) {
    size = std::max<uint64_t>(size, 1);
    for (auto it = free_.begin(); it != free_.end(); ++it) {
        const uint64_t range_begin = it->first;
        const uint64_t range_end = it->first + it->second;
        const uint64_t offset = align_up(range_begin, alignment);
        if (offset >= range_end || range_end - offset < size) continue;

        free_.erase(it);
        // The alignment gap before and the tail after stay free (and reusable).
        if (offset > range_begin) free_.emplace(range_begin, offset - range_begin);
        if (offset + size < range_end) free_.emplace(offset + size, range_end - offset - size);
        allocated_.emplace(offset, size);
        used_ += size;
        return offset;
    }
    return std::nullopt;
}

void BlockAllocator::free(uint64_t offset) {
    auto found = allocated_.find(offset);
    if (found == allocated_.end()) throw std::logic_error("BlockAllocator::free: unknown offset");
    uint64_t begin = offset;
    uint64_t end = offset + found->second;
    used_ -= found->second;
    allocated_.erase(found);

    // Merge with the free neighbours on both sides so large ranges come back.
    auto next = free_.lower_bound(begin);
    if (next != free_.end() && next->first == end) {
        end += next->second;
        next = free_.erase(next);
    }
    if (next != free_.begin()) {
        auto prev = std::prev(next);
        if (prev->first + prev->second == begin) {
            begin = prev->first;
            free_.erase(prev);
        }
    }
    free_.emplace(begin, end - begin);
}

uint64_t BlockAllocator::largest_free_range() const {
    uint64_t best = 0;
    for (const auto& [offset, size] : free_) best = std::max(best, size);
    return best;
}

std::optional<SubAllocation> BlockPool::try_allocate(uint64_t size, uint64_t alignment) {
    for (uint32_t i = 0; i < blocks_.size(); ++i) {
        if (std::optional<uint64_t> offset = blocks_[i].allocate(size, alignment))
            return SubAllocation{i, *offset, std::max<uint64_t>(size, 1)};
    }
    return std::nullopt;
}

uint32_t BlockPool::add_block() {
    blocks_.emplace_back(block_size_);
    return uint32_t(blocks_.size() - 1);
}

void BlockPool::free(const SubAllocation& allocation) {
    blocks_.at(allocation.block).free(allocation.offset);
}

}  // namespace ds::vk
