#include "renderer/passes/pass_util.h"

#include "renderer/vk/barrier.h"
#include "renderer/vk/check.h"
#include "renderer/vk/context.h"
#include "renderer/vk/functions.h"

namespace ds::passes {

FrameDescriptorPool::FrameDescriptorPool(vk::Context& context, uint32_t max_sets,
                                         std::span<const VkDescriptorPoolSize> sizes,
                                         const char* name) {
    for (vk::DescriptorPool& pool : pools_)
        pool = vk::DescriptorPool(context, max_sets, sizes, name);
    frames_.fill(UINT64_MAX);
}

VkDescriptorSet FrameDescriptorPool::allocate(uint64_t frame_number, VkDescriptorSetLayout layout) {
    const size_t slot = frame_number % pools_.size();
    if (frames_[slot] != frame_number) {
        pools_[slot].reset_sets();
        frames_[slot] = frame_number;
    }
    return pools_[slot].allocate(layout);
}

VkPipeline PipelineVariants::get(uint32_t key) {
    auto it = pipelines_.find(key);
    if (it == pipelines_.end()) it = pipelines_.emplace(key, create_(key, compile_(key))).first;
    return it->second.handle();
}

void PipelineVariants::rebuild(vk::DestroyList& retired) {
    std::map<uint32_t, ShaderStages> stages;
    for (const auto& [key, pipeline] : pipelines_) stages.emplace(key, compile_(key));
    std::map<uint32_t, vk::Pipeline> fresh;
    for (const auto& [key, s] : stages) fresh.emplace(key, create_(key, s));
    // An in-flight frame may still use the old pipelines.
    for (auto& [key, pipeline] : pipelines_) retired.defer(std::move(pipeline));
    pipelines_ = std::move(fresh);
}

VkRenderingAttachmentInfo attachment(VkImageView view, VkImageLayout layout,
                                     VkAttachmentLoadOp load, VkAttachmentStoreOp store) {
    auto a = vk::make<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
    a.imageView = view;
    a.imageLayout = layout;
    a.loadOp = load;
    a.storeOp = store;
    return a;
}

VkRenderingAttachmentInfo color_attachment(VkImageView view, VkAttachmentLoadOp load,
                                           std::array<float, 4> clear) {
    VkRenderingAttachmentInfo a = attachment(view, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, load,
                                             VK_ATTACHMENT_STORE_OP_STORE);
    for (size_t i = 0; i < 4; ++i) a.clearValue.color.float32[i] = clear[i];
    return a;
}

VkRenderingAttachmentInfo resolving_color_attachment(VkImageView msaa, VkImageView resolve,
                                                     VkAttachmentLoadOp load,
                                                     VkAttachmentStoreOp store,
                                                     std::array<float, 4> clear) {
    VkRenderingAttachmentInfo a = color_attachment(msaa, load, clear);
    a.storeOp = store;
    a.resolveMode = VK_RESOLVE_MODE_AVERAGE_BIT;
    a.resolveImageView = resolve;
    a.resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    return a;
}

VkRenderingAttachmentInfo depth_attachment(VkImageView view, VkImageLayout layout,
                                           VkAttachmentLoadOp load, VkAttachmentStoreOp store,
                                           float clear_depth) {
    VkRenderingAttachmentInfo a = attachment(view, layout, load, store);
    a.clearValue.depthStencil = {clear_depth, 0};
    return a;
}

void begin_rendering(VkCommandBuffer cmd, VkExtent2D extent,
                     std::span<const VkRenderingAttachmentInfo> colors,
                     const VkRenderingAttachmentInfo* depth) {
    auto info = vk::make<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
    info.renderArea = {{0, 0}, extent};
    info.layerCount = 1;
    info.colorAttachmentCount = uint32_t(colors.size());
    info.pColorAttachments = colors.data();
    info.pDepthAttachment = depth;
    vk::fn().cmd_begin_rendering(cmd, &info);
    const VkViewport viewport{0.0f, 0.0f, float(extent.width), float(extent.height), 0.0f, 1.0f};
    const VkRect2D scissor{{0, 0}, extent};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
}

void set_depth_state(VkCommandBuffer cmd, bool test, bool write, VkCompareOp compare) {
    vk::fn().cmd_set_depth_test_enable(cmd, test ? VK_TRUE : VK_FALSE);
    vk::fn().cmd_set_depth_write_enable(cmd, write ? VK_TRUE : VK_FALSE);
    vk::fn().cmd_set_depth_compare_op(cmd, compare);
}

vk::DescriptorSetLayout create_count_set_layout(vk::Context& context) {
    const VkDescriptorSetLayoutBinding binding =
        vk::layout_binding(0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_FRAGMENT_BIT);
    return vk::DescriptorSetLayout(context, {&binding, 1}, "count set layout");
}

void declare_counts(graph::PassBuilder& builder, graph::ImageHandle counts) {
    builder.write(counts, graph::Access::TransferDst);
    builder.write(counts, graph::Access::StorageReadWrite, graph::Shader::Fragment);
}

void clear_counts(VkCommandBuffer cmd, VkImage image) {
    const VkClearColorValue zero{};
    const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearColorImage(cmd, image, VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &range);
    vk::image_barrier(cmd, {.image = image,
                            .old_layout = VK_IMAGE_LAYOUT_GENERAL,
                            .new_layout = VK_IMAGE_LAYOUT_GENERAL,
                            .src_stage = VK_PIPELINE_STAGE_2_CLEAR_BIT,
                            .src_access = VK_ACCESS_2_TRANSFER_WRITE_BIT,
                            .dst_stage = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                            .dst_access = VK_ACCESS_2_SHADER_STORAGE_READ_BIT |
                                          VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT});
}

void write_count_set(VkDevice device, VkDescriptorSet set, VkImageView view) {
    const VkDescriptorImageInfo info{VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_GENERAL};
    auto write = vk::make<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
    write.dstSet = set;
    write.dstBinding = 0;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    write.pImageInfo = &info;
    vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);
}

}  // namespace ds::passes
