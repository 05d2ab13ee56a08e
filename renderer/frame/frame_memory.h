#pragma once
// Resource exhaustion as an error before the work (issue 12): a frame's size against the
// device's image and framebuffer limits, and its memory, estimated from what the graph
// declared, against the device-local heap (or VK_EXT_memory_budget's budget), refused with
// the estimate in the message instead of allocating until something gives.
#include <cstdint>
#include <span>
#include <string>

#include <vulkan/vulkan.h>

#include "renderer/graph/plan.h"
#include "renderer/vk/device_limits.h"

namespace ds {

// Bytes of one image: texels x samples x texel size, every mip level.
uint64_t image_bytes(VkFormat format, VkExtent2D extent, VkSampleCountFlagBits samples,
                     uint32_t mip_levels = 1);

struct FrameMemory {
    uint64_t bytes = 0;  // the frame's images and buffers, imported targets included
    std::string largest;
    uint64_t largest_bytes = 0;
    void add(const std::string& name, uint64_t resource_bytes);
};

// Every image and buffer the graph declared this frame (each history image once: previous
// and current are two resources).
FrameMemory frame_memory(std::span<const graph::ResourceInfo> resources);

// What the checks say about the frame in their one line.
struct FrameShape {
    std::string device;  // its name
    VkExtent2D size{0, 0};
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
};

// Throws ds::Error when the frame is wider or taller than maxImageDimension2D or the
// framebuffer limits allow.
void check_frame_size(const vk::DeviceLimits& limits, const FrameShape& shape);

// Throws ds::Error when frame + scene bytes exceed `budget` (vk::heap_budget), naming the
// estimate, its largest resource, the scene's share and the limit.
void check_frame_memory(const FrameMemory& frame, uint64_t scene_bytes, uint64_t budget,
                        const vk::DeviceLimits& limits, const FrameShape& shape);

}  // namespace ds
