#pragma once
// VkBuffer + its memory, move-only.
#include <cstddef>

#include <vulkan/vulkan.h>

#include "renderer/vk/memory.h"

namespace ds::vk {

class Context;

struct BufferDesc {
    VkDeviceSize size = 0;
    VkBufferUsageFlags usage = 0;
    MemoryUsage memory = MemoryUsage::GpuOnly;
    const char* name = nullptr;  // debug name (RenderDoc, validation messages)
};

class Buffer {
  public:
    Buffer() = default;
    Buffer(Context& context, const BufferDesc& desc);  // throws ds::Error
    ~Buffer() { reset(); }
    Buffer(Buffer&& other) noexcept { *this = std::move(other); }
    Buffer& operator=(Buffer&& other) noexcept;
    Buffer(const Buffer&) = delete;
    Buffer& operator=(const Buffer&) = delete;

    void reset();
    explicit operator bool() const { return buffer_ != VK_NULL_HANDLE; }
    VkBuffer handle() const { return buffer_; }
    VkDeviceSize size() const { return size_; }
    std::byte* mapped() const { return allocation_.mapped; }  // null unless host-visible

    // Host-visible buffers: copy in (then flush) / make GPU writes visible (then read mapped()).
    void write(const void* data, size_t size, size_t offset = 0);
    void invalidate() const;

  private:
    Context* context_ = nullptr;
    VkBuffer buffer_ = VK_NULL_HANDLE;
    VkDeviceSize size_ = 0;
    Allocation allocation_;
};

}  // namespace ds::vk
