#include "renderer/vk/features.h"

#include <algorithm>
#include <cstring>
#include <vector>

namespace ds::vk {

FeatureChain::FeatureChain() {
    base.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
    v12.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES;
    dynamic_rendering.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DYNAMIC_RENDERING_FEATURES;
    synchronization2.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SYNCHRONIZATION_2_FEATURES;
    extended_dynamic_state.sType =
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_EXTENDED_DYNAMIC_STATE_FEATURES_EXT;
    base.pNext = &v12;
    v12.pNext = &dynamic_rendering;
    dynamic_rendering.pNext = &synchronization2;
    synchronization2.pNext = &extended_dynamic_state;
}

bool has_device_extension(VkPhysicalDevice device, const char* name) {
    uint32_t count = 0;
    if (vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr) != VK_SUCCESS)
        return false;
    std::vector<VkExtensionProperties> exts(count);
    if (vkEnumerateDeviceExtensionProperties(device, nullptr, &count, exts.data()) != VK_SUCCESS)
        return false;
    return std::any_of(exts.begin(), exts.end(), [&](const VkExtensionProperties& e) {
        return std::strcmp(e.extensionName, name) == 0;
    });
}

bool has_promoted_extensions(VkPhysicalDevice device) {
    return std::all_of(kPromotedExtensions.begin(), kPromotedExtensions.end(),
                       [&](const char* name) { return has_device_extension(device, name); });
}

}  // namespace ds::vk
