#include "renderer/vk/descriptors.h"

#include <utility>

#include "renderer/vk/check.h"
#include "renderer/vk/context.h"

namespace ds::vk {

DescriptorSetLayout::DescriptorSetLayout(Context& context,
                                         std::span<const VkDescriptorSetLayoutBinding> bindings,
                                         const char* name)
    : device_(context.device()) {
    auto info =
        make<VkDescriptorSetLayoutCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
    info.bindingCount = uint32_t(bindings.size());
    info.pBindings = bindings.data();
    check(vkCreateDescriptorSetLayout(device_, &info, nullptr, &layout_),
          "vkCreateDescriptorSetLayout");
    context.set_name(VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, layout_, name);
}

DescriptorSetLayout& DescriptorSetLayout::operator=(DescriptorSetLayout&& other) noexcept {
    if (this == &other) return *this;
    reset();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    layout_ = std::exchange(other.layout_, VK_NULL_HANDLE);
    return *this;
}

void DescriptorSetLayout::reset() {
    if (layout_) vkDestroyDescriptorSetLayout(device_, layout_, nullptr);
    layout_ = VK_NULL_HANDLE;
}

DescriptorPool::DescriptorPool(Context& context, uint32_t max_sets,
                               std::span<const VkDescriptorPoolSize> sizes, const char* name)
    : device_(context.device()) {
    auto info = make<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
    info.maxSets = max_sets;
    info.poolSizeCount = uint32_t(sizes.size());
    info.pPoolSizes = sizes.data();
    check(vkCreateDescriptorPool(device_, &info, nullptr, &pool_), "vkCreateDescriptorPool");
    context.set_name(VK_OBJECT_TYPE_DESCRIPTOR_POOL, pool_, name);
}

DescriptorPool& DescriptorPool::operator=(DescriptorPool&& other) noexcept {
    if (this == &other) return *this;
    reset_handle();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    pool_ = std::exchange(other.pool_, VK_NULL_HANDLE);
    return *this;
}

void DescriptorPool::reset_handle() {
    if (pool_) vkDestroyDescriptorPool(device_, pool_, nullptr);
    pool_ = VK_NULL_HANDLE;
}

VkDescriptorSet DescriptorPool::allocate(VkDescriptorSetLayout layout) {
    auto info = make<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
    info.descriptorPool = pool_;
    info.descriptorSetCount = 1;
    info.pSetLayouts = &layout;
    VkDescriptorSet set = VK_NULL_HANDLE;
    check(vkAllocateDescriptorSets(device_, &info, &set), "vkAllocateDescriptorSets");
    return set;
}

void DescriptorPool::reset_sets() {
    check(vkResetDescriptorPool(device_, pool_, 0), "vkResetDescriptorPool");
}

DescriptorWriter& DescriptorWriter::buffer(uint32_t binding, VkDescriptorType type, VkBuffer buffer,
                                           VkDeviceSize offset, VkDeviceSize range) {
    buffers_.push_back({buffer, offset, range});
    auto write = make<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
    write.dstBinding = binding;
    write.descriptorCount = 1;
    write.descriptorType = type;
    write.pBufferInfo = &buffers_.back();
    writes_.push_back(write);
    return *this;
}

DescriptorWriter& DescriptorWriter::image(uint32_t binding, VkImageView view, VkSampler sampler,
                                          VkImageLayout layout) {
    images_.push_back({sampler, view, layout});
    auto write = make<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
    write.dstBinding = binding;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    write.pImageInfo = &images_.back();
    writes_.push_back(write);
    return *this;
}

DescriptorWriter& DescriptorWriter::storage_image(uint32_t binding, VkImageView view,
                                                  VkImageLayout layout) {
    image(binding, view, VK_NULL_HANDLE, layout);
    writes_.back().descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    return *this;
}

DescriptorWriter& DescriptorWriter::input_attachment(uint32_t binding, VkImageView view,
                                                     VkImageLayout layout) {
    image(binding, view, VK_NULL_HANDLE, layout);
    writes_.back().descriptorType = VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT;
    return *this;
}

void DescriptorWriter::update(VkDevice device, VkDescriptorSet set) {
    for (VkWriteDescriptorSet& w : writes_) w.dstSet = set;
    vkUpdateDescriptorSets(device, uint32_t(writes_.size()), writes_.data(), 0, nullptr);
}

}  // namespace ds::vk
