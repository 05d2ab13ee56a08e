#pragma once
// synchronization2 barriers with every field named at the call site.
#include <span>

#include <vulkan/vulkan.h>

namespace ds::vk {

struct ImageBarrier {
    VkImage image = VK_NULL_HANDLE;
    VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
    VkImageLayout old_layout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkImageLayout new_layout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkPipelineStageFlags2 src_stage = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 src_access = VK_ACCESS_2_NONE;
    VkPipelineStageFlags2 dst_stage = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 dst_access = VK_ACCESS_2_NONE;
    uint32_t base_mip = 0;
    uint32_t mip_count = VK_REMAINING_MIP_LEVELS;
};

void image_barriers(VkCommandBuffer cmd, std::span<const ImageBarrier> barriers);
inline void image_barrier(VkCommandBuffer cmd, const ImageBarrier& barrier) {
    image_barriers(cmd, {&barrier, 1});
}
// Global memory dependency (buffers, host reads of transfer results).
void memory_barrier(VkCommandBuffer cmd, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                    VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access);

}  // namespace ds::vk
