#include "renderer/vk/buffer.h"

#include <cstring>
#include <string>
#include <utility>

#include "renderer/common/error.h"
#include "renderer/vk/check.h"
#include "renderer/vk/context.h"

namespace ds::vk {

Buffer::Buffer(Context& context, const BufferDesc& desc) : context_(&context), size_(desc.size) {
    auto info = make<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
    info.size = desc.size;
    info.usage = desc.usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VkDevice device = context.device();
    check(vkCreateBuffer(device, &info, nullptr, &buffer_),
          ("vkCreateBuffer for buffer '" + std::string(desc.name ? desc.name : "unnamed") + "' (" +
           std::to_string(desc.size) + " bytes)")
              .c_str());

    auto dedicated =
        make<VkMemoryDedicatedRequirements>(VK_STRUCTURE_TYPE_MEMORY_DEDICATED_REQUIREMENTS);
    auto req = make<VkMemoryRequirements2>(VK_STRUCTURE_TYPE_MEMORY_REQUIREMENTS_2, &dedicated);
    auto req_info =
        make<VkBufferMemoryRequirementsInfo2>(VK_STRUCTURE_TYPE_BUFFER_MEMORY_REQUIREMENTS_INFO_2);
    req_info.buffer = buffer_;
    vkGetBufferMemoryRequirements2(device, &req_info, &req);

    AllocationRequest request;
    request.requirements = req.memoryRequirements;
    request.usage = desc.memory;
    request.kind = ResourceKind::Linear;
    request.dedicated =
        dedicated.prefersDedicatedAllocation || dedicated.requiresDedicatedAllocation;
    request.buffer = buffer_;
    request.name = desc.name;
    try {
        allocation_ = context.allocator().allocate(request);
        check(vkBindBufferMemory(device, buffer_, allocation_.memory, allocation_.offset),
              "vkBindBufferMemory");
    } catch (...) {
        reset();
        throw;
    }
    context.set_name(VK_OBJECT_TYPE_BUFFER, buffer_, desc.name);
}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
    if (this == &other) return *this;
    reset();
    context_ = std::exchange(other.context_, nullptr);
    buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
    size_ = std::exchange(other.size_, 0);
    allocation_ = std::exchange(other.allocation_, Allocation{});
    return *this;
}

void Buffer::reset() {
    if (!context_) return;
    if (buffer_) context_->clear_name(VK_OBJECT_TYPE_BUFFER, buffer_);
    if (buffer_) vkDestroyBuffer(context_->device(), buffer_, nullptr);
    context_->allocator().free(allocation_);
    buffer_ = VK_NULL_HANDLE;
    size_ = 0;
    context_ = nullptr;
}

void Buffer::write(const void* data, size_t size, size_t offset) {
    if (!allocation_.mapped) throw Error("Buffer::write on a buffer that is not host-visible");
    if (offset + size > size_) throw Error("Buffer::write past the end of the buffer");
    std::memcpy(allocation_.mapped + offset, data, size);
    context_->allocator().flush(allocation_);
}

void Buffer::invalidate() const {
    if (context_) context_->allocator().invalidate(allocation_);
}

}  // namespace ds::vk
