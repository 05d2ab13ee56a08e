#pragma once
// Descriptor set layouts, pools and writes. Plain sets only: lavapipe has no descriptor
// indexing, so materials get one small set each.
#include <cstdint>
#include <deque>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

namespace ds::vk {

class Context;

constexpr VkDescriptorSetLayoutBinding layout_binding(uint32_t binding, VkDescriptorType type,
                                                      VkShaderStageFlags stages) {
    return {binding, type, 1, stages, nullptr};
}

class DescriptorSetLayout {
  public:
    DescriptorSetLayout() = default;
    DescriptorSetLayout(Context& context, std::span<const VkDescriptorSetLayoutBinding> bindings,
                        const char* name = nullptr);
    ~DescriptorSetLayout() { reset(); }
    DescriptorSetLayout(DescriptorSetLayout&& other) noexcept { *this = std::move(other); }
    DescriptorSetLayout& operator=(DescriptorSetLayout&& other) noexcept;
    DescriptorSetLayout(const DescriptorSetLayout&) = delete;
    DescriptorSetLayout& operator=(const DescriptorSetLayout&) = delete;

    void reset();
    VkDescriptorSetLayout handle() const { return layout_; }

  private:
    VkDevice device_ = VK_NULL_HANDLE;
    VkDescriptorSetLayout layout_ = VK_NULL_HANDLE;
};

class DescriptorPool {
  public:
    DescriptorPool() = default;
    DescriptorPool(Context& context, uint32_t max_sets, std::span<const VkDescriptorPoolSize> sizes,
                   const char* name = nullptr);
    ~DescriptorPool() { reset_handle(); }
    DescriptorPool(DescriptorPool&& other) noexcept { *this = std::move(other); }
    DescriptorPool& operator=(DescriptorPool&& other) noexcept;
    DescriptorPool(const DescriptorPool&) = delete;
    DescriptorPool& operator=(const DescriptorPool&) = delete;

    VkDescriptorSet allocate(VkDescriptorSetLayout layout);  // throws when the pool is full
    void reset_sets();                                       // frees every set at once
    VkDescriptorPool handle() const { return pool_; }

  private:
    void reset_handle();

    VkDevice device_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
};

// Collects writes for one set, then applies them in one vkUpdateDescriptorSets call.
class DescriptorWriter {
  public:
    DescriptorWriter() = default;
    DescriptorWriter(const DescriptorWriter&) = delete;  // writes_ points into the deques
    DescriptorWriter& operator=(const DescriptorWriter&) = delete;

    DescriptorWriter& buffer(uint32_t binding, VkDescriptorType type, VkBuffer buffer,
                             VkDeviceSize offset = 0, VkDeviceSize range = VK_WHOLE_SIZE);
    DescriptorWriter& image(uint32_t binding, VkImageView view, VkSampler sampler,
                            VkImageLayout layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    DescriptorWriter& storage_image(uint32_t binding, VkImageView view,
                                    VkImageLayout layout = VK_IMAGE_LAYOUT_GENERAL);
    DescriptorWriter& input_attachment(uint32_t binding, VkImageView view, VkImageLayout layout);
    void update(VkDevice device, VkDescriptorSet set);

  private:
    // deques: pointers into them stay valid while more writes are added.
    std::deque<VkDescriptorBufferInfo> buffers_;
    std::deque<VkDescriptorImageInfo> images_;
    std::vector<VkWriteDescriptorSet> writes_;
};

}  // namespace ds::vk
