#include "renderer/frame/frame_memory.h"

#include <algorithm>

#include "renderer/common/error.h"
#include "renderer/format/format.h"

namespace ds {
namespace {

std::string frame_text(const FrameShape& shape) {
    return "a " + std::to_string(shape.size.width) + "x" + std::to_string(shape.size.height) +
           " frame at msaa=" + std::to_string(int(shape.samples));
}

}  // namespace

uint64_t image_bytes(VkFormat format, VkExtent2D extent, VkSampleCountFlagBits samples,
                     uint32_t mip_levels) {
    const uint64_t texel = std::max(format::bytes_per_texel(format), 1u);
    uint64_t total = 0;
    uint64_t w = extent.width, h = extent.height;
    for (uint32_t level = 0; level < std::max(mip_levels, 1u); ++level) {
        total += w * h * uint64_t(samples) * texel;
        w = std::max<uint64_t>(w / 2, 1);
        h = std::max<uint64_t>(h / 2, 1);
    }
    return total;
}

void FrameMemory::add(const std::string& name, uint64_t resource_bytes) {
    bytes += resource_bytes;
    if (resource_bytes > largest_bytes) {
        largest = name;
        largest_bytes = resource_bytes;
    }
}

FrameMemory frame_memory(std::span<const graph::ResourceInfo> resources) {
    FrameMemory m;
    for (const graph::ResourceInfo& r : resources)
        m.add(r.name, r.is_image ? image_bytes(r.image.format, r.extent, r.image.samples,
                                               r.image.mip_levels)
                                 : r.size);
    return m;
}

void check_frame_size(const vk::DeviceLimits& l, const FrameShape& shape) {
    const uint32_t max_w = std::min(l.max_image_dimension_2d, l.max_framebuffer_width);
    const uint32_t max_h = std::min(l.max_image_dimension_2d, l.max_framebuffer_height);
    if (shape.size.width <= max_w && shape.size.height <= max_h) return;
    throw Error(frame_text(shape) + " is larger than " + shape.device + " allows: at most " +
                std::to_string(max_w) + "x" + std::to_string(max_h) + " (maxImageDimension2D " +
                std::to_string(l.max_image_dimension_2d) + ", maxFramebufferWidth " +
                std::to_string(l.max_framebuffer_width) + ", maxFramebufferHeight " +
                std::to_string(l.max_framebuffer_height) + ")");
}

void check_frame_memory(const FrameMemory& frame, uint64_t scene_bytes, uint64_t budget,
                        const vk::DeviceLimits& l, const FrameShape& shape) {
    const uint64_t need = frame.bytes + scene_bytes;
    if (need <= budget) return;
    const std::string limit = budget < l.heap_bytes
                                  ? vk::bytes_text(budget) + " that VK_EXT_memory_budget leaves"
                                  : "the " + vk::bytes_text(l.heap_bytes) + " device-local heap";
    throw Error(frame_text(shape) + " needs about " + vk::bytes_text(need) +
                " of device memory (its images and buffers " + vk::bytes_text(frame.bytes) +
                ", the largest '" + frame.largest + "' " + vk::bytes_text(frame.largest_bytes) +
                "; the scene " + vk::bytes_text(scene_bytes) + "): more than " + limit + " of " +
                shape.device + (l.lowered ? " (lowered by DEPTHSCOPE_DEVICE_LIMITS)" : ""));
}

}  // namespace ds
