#include "renderer/vk/upload.h"

#include <algorithm>
#include <string>

#include "renderer/common/error.h"
#include "renderer/format/format.h"
#include "renderer/vk/barrier.h"
#include "renderer/vk/context.h"

namespace ds::vk {
namespace {

constexpr VkPipelineStageFlags2 kSampledStages =
    VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;

VkBufferImageCopy level_copy(VkDeviceSize offset, uint32_t level, uint32_t w, uint32_t h) {
    VkBufferImageCopy region{};
    region.bufferOffset = offset;
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, 1};
    region.imageExtent = {w, h, 1};
    return region;
}

}  // namespace

bool supports_blit_mips(const Context& context, VkFormat format) {
    const VkFormatFeatureFlags need = VK_FORMAT_FEATURE_BLIT_SRC_BIT |
                                      VK_FORMAT_FEATURE_BLIT_DST_BIT |
                                      VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
    return (context.format_properties(format).optimalTilingFeatures & need) == need;
}

Buffer& UploadBatch::stage(const void* data, size_t size) {
    staging_.emplace_back(context_, BufferDesc{size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                               MemoryUsage::Upload, "staging"});
    staging_.back().write(data, size);
    return staging_.back();
}

void UploadBatch::buffer(const Buffer& dst, const void* data, size_t size,
                         VkDeviceSize dst_offset) {
    if (size == 0) return;
    VkBuffer src = stage(data, size).handle();
    VkBuffer dst_handle = dst.handle();
    commands_.push_back([=](VkCommandBuffer cmd) {
        VkBufferCopy region{0, dst_offset, size};
        vkCmdCopyBuffer(cmd, src, dst_handle, 1, &region);
    });
}

MipFill UploadBatch::texture(const Image& dst, std::span<const uint8_t* const> levels) {
    const uint32_t count = dst.mip_levels();
    if (levels.empty() || (levels.size() != 1 && levels.size() != count))
        throw Error("texture upload: " + std::to_string(levels.size()) + " levels given for " +
                    std::to_string(count));
    const bool blit = count > 1 && levels.size() == 1;
    if (blit && !supports_blit_mips(context_, dst.format()))
        throw Error("texture upload: " + format::name(dst.format()) +
                    " cannot be blitted: every level must be given");

    // The given levels, packed one after another in one staging buffer.
    std::vector<uint8_t> packed;
    std::vector<VkBufferImageCopy> regions;
    uint32_t w = dst.width(), h = dst.height();
    for (uint32_t i = 0; i < levels.size(); ++i) {
        regions.push_back(level_copy(packed.size(), i, w, h));
        packed.insert(packed.end(), levels[i], levels[i] + size_t(w) * h * 4);
        w = std::max(w / 2, 1u);
        h = std::max(h / 2, 1u);
    }
    VkBuffer src = stage(packed.data(), packed.size()).handle();
    const Image* image = &dst;
    commands_.push_back([=](VkCommandBuffer cmd) {
        image_barrier(cmd,
                      {.image = image->handle(),
                       .old_layout = VK_IMAGE_LAYOUT_UNDEFINED,
                       .new_layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                       // Copies fill level 0 and blits the rest: order both after it.
                       .dst_stage = VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_BLIT_BIT,
                       .dst_access = VK_ACCESS_2_TRANSFER_WRITE_BIT});
        vkCmdCopyBufferToImage(cmd, src, image->handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                               uint32_t(regions.size()), regions.data());
        if (blit) {
            record_blit_mips(cmd, *image);
            return;
        }
        image_barrier(cmd, {.image = image->handle(),
                            .old_layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                            .new_layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                            .src_stage = VK_PIPELINE_STAGE_2_COPY_BIT,
                            .src_access = VK_ACCESS_2_TRANSFER_WRITE_BIT,
                            .dst_stage = kSampledStages,
                            .dst_access = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
    });
    return count == 1 ? MipFill::None : (blit ? MipFill::Blit : MipFill::Cpu);
}

void record_blit_mips(VkCommandBuffer cmd, const Image& image) {
    const VkImage handle = image.handle();
    int32_t w = int32_t(image.width()), h = int32_t(image.height());
    for (uint32_t i = 1; i < image.mip_levels(); ++i) {
        image_barrier(cmd,
                      {.image = handle,
                       .old_layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                       .new_layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                       .src_stage = VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_BLIT_BIT,
                       .src_access = VK_ACCESS_2_TRANSFER_WRITE_BIT,
                       .dst_stage = VK_PIPELINE_STAGE_2_BLIT_BIT,
                       .dst_access = VK_ACCESS_2_TRANSFER_READ_BIT,
                       .base_mip = i - 1,
                       .mip_count = 1});
        const int32_t nw = std::max(w / 2, 1), nh = std::max(h / 2, 1);
        VkImageBlit blit{};
        blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, i - 1, 0, 1};
        blit.srcOffsets[1] = {w, h, 1};
        blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, i, 0, 1};
        blit.dstOffsets[1] = {nw, nh, 1};
        vkCmdBlitImage(cmd, handle, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, handle,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_LINEAR);
        w = nw;
        h = nh;
    }
    const uint32_t last = image.mip_levels() - 1;
    const ImageBarrier done[] = {
        {.image = handle,
         .old_layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
         .new_layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
         .src_stage = VK_PIPELINE_STAGE_2_BLIT_BIT,
         .src_access = VK_ACCESS_2_NONE,  // reads need no availability, only ordering
         .dst_stage = kSampledStages,
         .dst_access = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
         .base_mip = 0,
         .mip_count = last},
        {.image = handle,
         .old_layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
         .new_layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
         .src_stage = VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_BLIT_BIT,
         .src_access = VK_ACCESS_2_TRANSFER_WRITE_BIT,
         .dst_stage = kSampledStages,
         .dst_access = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
         .base_mip = last,
         .mip_count = 1}};
    image_barriers(cmd, done);
}

void UploadBatch::submit() {
    if (commands_.empty()) return;
    context_.submit_once([&](VkCommandBuffer cmd) {
        for (auto& record : commands_) record(cmd);
        // Buffer copies become visible to every later read (vertex, index, uniform, storage).
        memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT);
    });
    commands_.clear();
    staging_.clear();
}

void clear_image_once(Context& context, const Image& image, const VkClearValue& value) {
    const VkImageAspectFlags aspect = image.aspect();
    context.submit_once([&](VkCommandBuffer cmd) {
        ImageBarrier b{.image = image.handle(),
                       .aspect = aspect,
                       .new_layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                       .dst_stage = VK_PIPELINE_STAGE_2_CLEAR_BIT,
                       .dst_access = VK_ACCESS_2_TRANSFER_WRITE_BIT};
        image_barrier(cmd, b);
        const VkImageSubresourceRange range{aspect, 0, VK_REMAINING_MIP_LEVELS, 0, 1};
        if (aspect & VK_IMAGE_ASPECT_COLOR_BIT)
            vkCmdClearColorImage(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                 &value.color, 1, &range);
        else
            vkCmdClearDepthStencilImage(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                        &value.depthStencil, 1, &range);
        b.old_layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
        b.new_layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
        b.src_stage = VK_PIPELINE_STAGE_2_CLEAR_BIT;
        b.src_access = VK_ACCESS_2_TRANSFER_WRITE_BIT;
        b.dst_stage = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
        b.dst_access = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
        image_barrier(cmd, b);
    });
}

}  // namespace ds::vk
