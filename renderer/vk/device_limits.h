#pragma once
// The device limits a frame can run into (image and framebuffer size, one allocation, the
// device-local heap), queried once, and the memory budget (VK_EXT_memory_budget) queried when
// asked. DEPTHSCOPE_DEVICE_LIMITS lowers them, to try what a smaller device does.
#include <cstdint>
#include <optional>
#include <string>

#include <vulkan/vulkan.h>

namespace ds::vk {

struct DeviceLimits {
    uint32_t max_image_dimension_2d = 0;
    uint32_t max_framebuffer_width = 0;
    uint32_t max_framebuffer_height = 0;
    uint64_t max_memory_allocation_size = 0;  // maintenance3 (0: not reported)
    // The largest DEVICE_LOCAL heap: where GpuOnly memory (attachments, textures) goes.
    uint32_t heap_index = UINT32_MAX;
    uint64_t heap_bytes = 0;
    bool memory_budget = false;  // VK_EXT_memory_budget is supported
    bool lowered = false;        // DEPTHSCOPE_DEVICE_LIMITS changed something
};

DeviceLimits probe_limits(VkPhysicalDevice device, uint32_t api_version);

// Lowers `limits` by a DEPTHSCOPE_DEVICE_LIMITS text: "image=N" (maxImageDimension2D and the
// framebuffer width and height), "heap_mib=N", "allocation_mib=N" (maxMemoryAllocationSize),
// separated by spaces or commas. Only lowers; throws ds::Error for anything else.
void apply_limit_overrides(DeviceLimits& limits, const std::string& text);

// What this process may use of the heap now: VK_EXT_memory_budget's heapBudget where the device
// has it, else the heap's size (both as lowered by DEPTHSCOPE_DEVICE_LIMITS).
uint64_t heap_budget(VkPhysicalDevice device, const DeviceLimits& limits);

// "512 B", "64.0 MiB", "10.5 GiB".
std::string bytes_text(uint64_t bytes);

}  // namespace ds::vk
