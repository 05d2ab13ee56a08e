#include "renderer/vk/device_limits.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string_view>
#include <vector>

#include "renderer/common/error.h"
#include "renderer/vk/check.h"
#include "renderer/vk/features.h"

namespace ds::vk {
namespace {

template <typename T>
void lower(T& value, uint64_t to, bool& lowered) {
    if (to < uint64_t(value)) {
        value = T(to);
        lowered = true;
    }
}

}  // namespace

DeviceLimits probe_limits(VkPhysicalDevice device, uint32_t api_version) {
    DeviceLimits l;
    auto maintenance3 = make<VkPhysicalDeviceMaintenance3Properties>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES);
    auto props = make<VkPhysicalDeviceProperties2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2,
                                                   &maintenance3);
    if (api_version >= VK_API_VERSION_1_1) {
        vkGetPhysicalDeviceProperties2(device, &props);
        l.max_memory_allocation_size = maintenance3.maxMemoryAllocationSize;
    } else {
        vkGetPhysicalDeviceProperties(device, &props.properties);
    }
    l.max_image_dimension_2d = props.properties.limits.maxImageDimension2D;
    l.max_framebuffer_width = props.properties.limits.maxFramebufferWidth;
    l.max_framebuffer_height = props.properties.limits.maxFramebufferHeight;

    VkPhysicalDeviceMemoryProperties mem{};
    vkGetPhysicalDeviceMemoryProperties(device, &mem);
    for (uint32_t i = 0; i < mem.memoryHeapCount; ++i)
        if ((mem.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT) &&
            mem.memoryHeaps[i].size > l.heap_bytes) {
            l.heap_index = i;
            l.heap_bytes = mem.memoryHeaps[i].size;
        }
    l.memory_budget = api_version >= VK_API_VERSION_1_1 &&
                      has_device_extension(device, VK_EXT_MEMORY_BUDGET_EXTENSION_NAME);
    if (const char* env = std::getenv("DEPTHSCOPE_DEVICE_LIMITS")) apply_limit_overrides(l, env);
    return l;
}

void apply_limit_overrides(DeviceLimits& l, const std::string& text) {
    std::string_view rest = text;
    while (!rest.empty()) {
        const size_t end = std::min(rest.find_first_of(" ,"), rest.size());
        const std::string_view item = rest.substr(0, end);
        rest.remove_prefix(std::min(end + 1, rest.size()));
        if (item.empty()) continue;
        const size_t eq = item.find('=');
        uint64_t value = 0;
        const std::string_view key = item.substr(0, eq);
        const std::string_view number = eq == item.npos ? "" : item.substr(eq + 1);
        const auto parsed = std::from_chars(number.data(), number.data() + number.size(), value);
        if (number.empty() || parsed.ec != std::errc() ||
            parsed.ptr != number.data() + number.size() || value == 0 || value > (1ull << 40))
            throw Error("DEPTHSCOPE_DEVICE_LIMITS: expected NAME=N (N a whole number > 0), got '" +
                        std::string(item) + "'");
        if (key == "image") {
            lower(l.max_image_dimension_2d, value, l.lowered);
            lower(l.max_framebuffer_width, value, l.lowered);
            lower(l.max_framebuffer_height, value, l.lowered);
        } else if (key == "heap_mib") {
            lower(l.heap_bytes, value << 20, l.lowered);
        } else if (key == "allocation_mib") {
            if (l.max_memory_allocation_size == 0) l.max_memory_allocation_size = UINT64_MAX;
            lower(l.max_memory_allocation_size, value << 20, l.lowered);
        } else {
            throw Error("DEPTHSCOPE_DEVICE_LIMITS: unknown limit '" + std::string(key) +
                        "' (image, heap_mib, allocation_mib)");
        }
    }
}

uint64_t heap_budget(VkPhysicalDevice device, const DeviceLimits& l) {
    if (!l.memory_budget || l.heap_index == UINT32_MAX) return l.heap_bytes;
    auto budget = make<VkPhysicalDeviceMemoryBudgetPropertiesEXT>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MEMORY_BUDGET_PROPERTIES_EXT);
    auto mem = make<VkPhysicalDeviceMemoryProperties2>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MEMORY_PROPERTIES_2, &budget);
    vkGetPhysicalDeviceMemoryProperties2(device, &mem);
    const uint64_t reported = budget.heapBudget[l.heap_index];
    return reported == 0 ? l.heap_bytes : std::min(reported, l.heap_bytes);
}

std::string bytes_text(uint64_t bytes) {
    char text[32];
    if (bytes < (1ull << 20)) {
        std::snprintf(text, sizeof text, "%llu B", static_cast<unsigned long long>(bytes));
    } else if (bytes < (1ull << 30)) {
        std::snprintf(text, sizeof text, "%.1f MiB", double(bytes) / double(1ull << 20));
    } else {
        std::snprintf(text, sizeof text, "%.1f GiB", double(bytes) / double(1ull << 30));
    }
    return text;
}

}  // namespace ds::vk
