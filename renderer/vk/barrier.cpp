#include "renderer/vk/barrier.h"
#include "renderer/vk/functions.h"

#include "renderer/vk/check.h"

#include <vector>

namespace ds::vk {

void image_barriers(VkCommandBuffer cmd, std::span<const ImageBarrier> barriers) {
    std::vector<VkImageMemoryBarrier2> vk_barriers;
    vk_barriers.reserve(barriers.size());
    for (const ImageBarrier& b : barriers) {
        auto v = make<VkImageMemoryBarrier2>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2);
        v.srcStageMask = b.src_stage;
        v.srcAccessMask = b.src_access;
        v.dstStageMask = b.dst_stage;
        v.dstAccessMask = b.dst_access;
        v.oldLayout = b.old_layout;
        v.newLayout = b.new_layout;
        v.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        v.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        v.image = b.image;
        v.subresourceRange = {b.aspect, b.base_mip, b.mip_count, 0, VK_REMAINING_ARRAY_LAYERS};
        vk_barriers.push_back(v);
    }
    auto dep = make<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
    dep.imageMemoryBarrierCount = uint32_t(vk_barriers.size());
    dep.pImageMemoryBarriers = vk_barriers.data();
    fn().cmd_pipeline_barrier2(cmd, &dep);
}

void memory_barrier(VkCommandBuffer cmd, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                    VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access) {
    auto barrier = make<VkMemoryBarrier2>(VK_STRUCTURE_TYPE_MEMORY_BARRIER_2);
    barrier.srcStageMask = src_stage;
    barrier.srcAccessMask = src_access;
    barrier.dstStageMask = dst_stage;
    barrier.dstAccessMask = dst_access;
    auto dep = make<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
    dep.memoryBarrierCount = 1;
    dep.pMemoryBarriers = &barrier;
    fn().cmd_pipeline_barrier2(cmd, &dep);
}

}  // namespace ds::vk
