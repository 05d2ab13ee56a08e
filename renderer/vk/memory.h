#pragma once
// Device memory: large blocks per memory type, sub-allocated by BlockPool (VMA is not packaged
// in Debian 12). Very large or driver-preferred resources get a dedicated allocation.
// Host-visible memory stays mapped for the block's lifetime.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/vk/block_allocator.h"

namespace ds::vk {

enum class MemoryUsage : uint8_t {
    GpuOnly,   // DEVICE_LOCAL: attachments, textures, vertex data
    Upload,    // HOST_VISIBLE (coherent preferred): staging, per-frame constants
    Readback,  // HOST_VISIBLE (cached preferred): image and query read-back
    // Transient attachments (tile memory on a tiler): LAZILY_ALLOCATED where the device has
    // it, else what GpuOnly gets. Always a dedicated allocation.
    Lazy,
};

// Linear (buffers, linear images) and optimal images live in separate pools: that is how
// bufferImageGranularity is respected without padding.
enum class ResourceKind : uint8_t { Linear, Optimal };

struct AllocationRequest {
    VkMemoryRequirements requirements{};
    MemoryUsage usage = MemoryUsage::GpuOnly;
    ResourceKind kind = ResourceKind::Linear;
    bool dedicated = false;            // VkMemoryDedicatedRequirements said prefers/requires
    VkBuffer buffer = VK_NULL_HANDLE;  // the resource, for VkMemoryDedicatedAllocateInfo
    VkImage image = VK_NULL_HANDLE;
    const char* name = nullptr;  // the resource's name, for the error when memory runs out
};

struct Allocation {
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize offset = 0;
    VkDeviceSize size = 0;
    std::byte* mapped = nullptr;  // host-visible memory only; already offset
    uint32_t memory_type = 0;
    bool coherent = true;
    bool lazily_allocated = false;  // the memory type is LAZILY_ALLOCATED
    // Bookkeeping for free(): pool index, or -1 for a dedicated allocation.
    int32_t pool = -1;
    SubAllocation sub;
    explicit operator bool() const { return memory != VK_NULL_HANDLE; }
};

struct MemoryStats {
    uint32_t blocks = 0;
    uint32_t dedicated = 0;
    uint64_t block_bytes = 0;
    uint64_t used_bytes = 0;  // sub-allocated + dedicated
};

class Allocator {
  public:
    static constexpr VkDeviceSize kDefaultBlockSize = 64ull << 20;

    // `max_allocation`: the device's maxMemoryAllocationSize (0: unknown); a larger request is
    // refused before vkAllocateMemory.
    Allocator(VkPhysicalDevice physical_device, VkDevice device,
              VkDeviceSize block_size = kDefaultBlockSize, VkDeviceSize max_allocation = 0);
    ~Allocator();
    Allocator(const Allocator&) = delete;
    Allocator& operator=(const Allocator&) = delete;

    // Throws ds::Error naming the resource (name, buffer or image, bytes) and the VkResult
    // (VK_ERROR_OUT_OF_DEVICE_MEMORY...) or the limit it ran into.
    Allocation allocate(const AllocationRequest& request);
    void free(Allocation& allocation);  // resets it; null is a no-op
    // No-ops for coherent memory; otherwise the range is widened to nonCoherentAtomSize.
    void flush(const Allocation& allocation) const;
    void invalidate(const Allocation& allocation) const;

    VkDevice device() const { return device_; }
    MemoryStats stats() const;

  private:
    struct Pool {
        uint32_t memory_type;
        ResourceKind kind;
        BlockPool blocks;
        std::vector<VkDeviceMemory> memories;
        std::vector<std::byte*> mapped;
    };

    uint32_t choose_memory_type(uint32_t type_bits, MemoryUsage usage) const;
    VkDeviceMemory allocate_memory(VkDeviceSize size, uint32_t type, const void* next,
                                   const AllocationRequest& request);
    std::byte* map_if_host_visible(VkDeviceMemory memory, uint32_t type);
    Allocation allocate_dedicated(const AllocationRequest& request, uint32_t type);
    Pool& pool_for(uint32_t type, ResourceKind kind, int32_t& index);
    VkMappedMemoryRange atom_range(const Allocation& allocation) const;

    VkDevice device_;
    VkDeviceSize block_size_;
    VkDeviceSize atom_size_;
    VkDeviceSize max_allocation_;
    VkPhysicalDeviceMemoryProperties props_{};
    std::vector<std::unique_ptr<Pool>> pools_;
    uint32_t dedicated_count_ = 0;
    uint64_t dedicated_bytes_ = 0;
    // allocate, free and stats: the inspector's render and UI threads both make images.
    mutable std::mutex mutex_;
};

}  // namespace ds::vk
