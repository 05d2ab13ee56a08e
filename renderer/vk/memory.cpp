#include "renderer/vk/memory.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "renderer/common/error.h"
#include "renderer/vk/check.h"
#include "renderer/vk/device_limits.h"

namespace ds::vk {
namespace {

struct TypeWish {
    VkMemoryPropertyFlags required;
    VkMemoryPropertyFlags preferred;
};

TypeWish wish_for(MemoryUsage usage) {
    switch (usage) {
        case MemoryUsage::GpuOnly:
            return {0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT};
        case MemoryUsage::Upload:
            return {VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT, VK_MEMORY_PROPERTY_HOST_COHERENT_BIT};
        case MemoryUsage::Readback:
            return {VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT,
                    VK_MEMORY_PROPERTY_HOST_CACHED_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT};
        case MemoryUsage::Lazy:
            return {0,
                    VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT | VK_MEMORY_PROPERTY_LAZILY_ALLOCATED_BIT};
    }
    return {0, 0};
}

const char* usage_name(MemoryUsage usage) {
    switch (usage) {
        case MemoryUsage::GpuOnly:
            return "gpu-only";
        case MemoryUsage::Upload:
            return "upload";
        case MemoryUsage::Readback:
            return "readback";
        case MemoryUsage::Lazy:
            return "lazily allocated";
    }
    return "?";
}

// "image 'hdr' (2147483648 bytes)": what an allocation error names.
std::string describe(const AllocationRequest& request) {
    const char* kind = request.image ? "image" : request.buffer ? "buffer" : "memory";
    return std::string(kind) + " '" + (request.name ? request.name : "unnamed") + "' (" +
           std::to_string(request.requirements.size) + " bytes, " +
           bytes_text(request.requirements.size) + ")";
}

}  // namespace

Allocator::Allocator(VkPhysicalDevice physical_device, VkDevice device, VkDeviceSize block_size,
                     VkDeviceSize max_allocation)
    : device_(device), block_size_(block_size), max_allocation_(max_allocation) {
    vkGetPhysicalDeviceMemoryProperties(physical_device, &props_);
    VkPhysicalDeviceProperties props{};
    vkGetPhysicalDeviceProperties(physical_device, &props);
    atom_size_ = std::max<VkDeviceSize>(props.limits.nonCoherentAtomSize, 1);
}

Allocator::~Allocator() {
    for (auto& pool : pools_) {
        for (uint32_t i = 0; i < pool->memories.size(); ++i) {
            if (!pool->blocks.block(i).empty())
                std::fprintf(stderr, "depthscope: warning: %zu allocation(s) leaked in a block\n",
                             pool->blocks.block(i).allocation_count());
            vkFreeMemory(device_, pool->memories[i], nullptr);  // also unmaps
        }
    }
}

uint32_t Allocator::choose_memory_type(uint32_t type_bits, MemoryUsage usage) const {
    const TypeWish wish = wish_for(usage);
    // Best = has every required bit and the most preferred bits; first index wins ties.
    int best = -1;
    int best_score = -1;
    for (uint32_t i = 0; i < props_.memoryTypeCount; ++i) {
        const VkMemoryPropertyFlags flags = props_.memoryTypes[i].propertyFlags;
        if (!(type_bits & (1u << i)) || (flags & wish.required) != wish.required) continue;
        const int score = __builtin_popcount(flags & wish.preferred);
        if (score > best_score) {
            best = int(i);
            best_score = score;
        }
    }
    if (best < 0)
        throw Error(std::string("no memory type for a ") + usage_name(usage) +
                    " resource (memoryTypeBits " + std::to_string(type_bits) + ")");
    return uint32_t(best);
}

VkDeviceMemory Allocator::allocate_memory(VkDeviceSize size, uint32_t type, const void* next,
                                          const AllocationRequest& request) {
    auto info = make<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
    info.pNext = next;
    info.allocationSize = size;
    info.memoryTypeIndex = type;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    // One line that says what was being allocated: VK_ERROR_OUT_OF_DEVICE_MEMORY alone does not.
    const VkResult result = vkAllocateMemory(device_, &info, nullptr, &memory);
    if (result != VK_SUCCESS) {
        const std::string what = "vkAllocateMemory of " + bytes_text(size) +
                                 (size == request.requirements.size ? "" : " (a block)") + " for " +
                                 describe(request);
        check(result, what.c_str());
    }
    return memory;
}

std::byte* Allocator::map_if_host_visible(VkDeviceMemory memory, uint32_t type) {
    if (!(props_.memoryTypes[type].propertyFlags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT))
        return nullptr;
    void* data = nullptr;
    VkResult result = vkMapMemory(device_, memory, 0, VK_WHOLE_SIZE, 0, &data);
    if (result != VK_SUCCESS) {
        vkFreeMemory(device_, memory, nullptr);
        check(result, "vkMapMemory");
    }
    return static_cast<std::byte*>(data);
}

Allocation Allocator::allocate_dedicated(const AllocationRequest& request, uint32_t type) {
    auto dedicated =
        make<VkMemoryDedicatedAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_DEDICATED_ALLOCATE_INFO);
    dedicated.buffer = request.buffer;
    dedicated.image = request.image;
    const bool has_target = request.buffer || request.image;
    Allocation a;
    a.size = request.requirements.size;
    a.memory = allocate_memory(a.size, type, has_target ? &dedicated : nullptr, request);
    a.mapped = map_if_host_visible(a.memory, type);
    a.memory_type = type;
    a.coherent = props_.memoryTypes[type].propertyFlags & VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    a.lazily_allocated =
        props_.memoryTypes[type].propertyFlags & VK_MEMORY_PROPERTY_LAZILY_ALLOCATED_BIT;
    a.pool = -1;
    ++dedicated_count_;
    dedicated_bytes_ += a.size;
    return a;
}

Allocator::Pool& Allocator::pool_for(uint32_t type, ResourceKind kind, int32_t& index) {
    for (size_t i = 0; i < pools_.size(); ++i) {
        if (pools_[i]->memory_type == type && pools_[i]->kind == kind) {
            index = int32_t(i);
            return *pools_[i];
        }
    }
    pools_.push_back(std::make_unique<Pool>(Pool{type, kind, BlockPool(block_size_), {}, {}}));
    index = int32_t(pools_.size() - 1);
    return *pools_.back();
}

Allocation Allocator::allocate(const AllocationRequest& request) {
    std::lock_guard lock(mutex_);
    const VkMemoryRequirements& req = request.requirements;
    if (max_allocation_ && req.size > max_allocation_)
        throw Error(describe(request) + " is larger than the device's maxMemoryAllocationSize (" +
                    bytes_text(max_allocation_) + ")");
    const uint32_t type = choose_memory_type(req.memoryTypeBits, request.usage);
    // Anything over half a block would waste most of a block: give it its own memory.
    if (request.dedicated || request.usage == MemoryUsage::Lazy || req.size > block_size_ / 2)
        return allocate_dedicated(request, type);

    int32_t pool_index = -1;
    Pool& pool = pool_for(type, request.kind, pool_index);
    std::optional<SubAllocation> sub = pool.blocks.try_allocate(req.size, req.alignment);
    if (!sub) {
        // Create the memory first so a failure leaves the pool unchanged.
        VkDeviceMemory memory = allocate_memory(block_size_, type, nullptr, request);
        std::byte* mapped = map_if_host_visible(memory, type);
        pool.memories.push_back(memory);
        pool.mapped.push_back(mapped);
        pool.blocks.add_block();
        sub = pool.blocks.try_allocate(req.size, req.alignment);
        if (!sub) throw Error("memory: allocation does not fit an empty block");
    }
    Allocation a;
    a.memory = pool.memories[sub->block];
    a.offset = sub->offset;
    a.size = sub->size;
    a.mapped = pool.mapped[sub->block] ? pool.mapped[sub->block] + sub->offset : nullptr;
    a.memory_type = type;
    a.coherent = props_.memoryTypes[type].propertyFlags & VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    a.lazily_allocated =
        props_.memoryTypes[type].propertyFlags & VK_MEMORY_PROPERTY_LAZILY_ALLOCATED_BIT;
    a.pool = pool_index;
    a.sub = *sub;
    return a;
}

void Allocator::free(Allocation& allocation) {
    std::lock_guard lock(mutex_);
    if (!allocation) return;
    if (allocation.pool < 0) {
        vkFreeMemory(device_, allocation.memory, nullptr);
        --dedicated_count_;
        dedicated_bytes_ -= allocation.size;
    } else {
        // Empty blocks are kept: the next frame (resize, scene reload) usually needs them again.
        pools_.at(size_t(allocation.pool))->blocks.free(allocation.sub);
    }
    allocation = Allocation{};
}

VkMappedMemoryRange Allocator::atom_range(const Allocation& a) const {
    auto range = make<VkMappedMemoryRange>(VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE);
    range.memory = a.memory;
    range.offset = a.offset / atom_size_ * atom_size_;
    const VkDeviceSize end = align_up(a.offset + a.size, atom_size_);
    range.size = (a.pool < 0 || end >= block_size_) ? VK_WHOLE_SIZE : end - range.offset;
    return range;
}

void Allocator::flush(const Allocation& a) const {
    if (a.coherent || !a.mapped) return;
    VkMappedMemoryRange range = atom_range(a);
    check(vkFlushMappedMemoryRanges(device_, 1, &range), "vkFlushMappedMemoryRanges");
}

void Allocator::invalidate(const Allocation& a) const {
    if (a.coherent || !a.mapped) return;
    VkMappedMemoryRange range = atom_range(a);
    check(vkInvalidateMappedMemoryRanges(device_, 1, &range), "vkInvalidateMappedMemoryRanges");
}

MemoryStats Allocator::stats() const {
    std::lock_guard lock(mutex_);
    MemoryStats s;
    s.dedicated = dedicated_count_;
    s.used_bytes = dedicated_bytes_;
    for (const auto& pool : pools_) {
        s.blocks += uint32_t(pool->blocks.block_count());
        s.block_bytes += pool->blocks.block_count() * block_size_;
        for (uint32_t i = 0; i < pool->blocks.block_count(); ++i)
            s.used_bytes += pool->blocks.block(i).used();
    }
    return s;
}

}  // namespace ds::vk
