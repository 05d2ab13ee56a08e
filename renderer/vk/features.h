#pragma once
// The Vulkan 1.3 features depthscope needs, chained as their own structs. The same chain is
// valid on a 1.3 device (core) and on a 1.2 device that has the extensions, which is how
// lavapipe looks under RenderDoc. Probe and device creation use it alike.
#include <array>

#include <vulkan/vulkan.h>

namespace ds::vk {

inline constexpr std::array<const char*, 3> kPromotedExtensions = {
    VK_KHR_DYNAMIC_RENDERING_EXTENSION_NAME, VK_KHR_SYNCHRONIZATION_2_EXTENSION_NAME,
    VK_EXT_EXTENDED_DYNAMIC_STATE_EXTENSION_NAME};

struct FeatureChain {
    VkPhysicalDeviceFeatures2 base{};
    VkPhysicalDeviceVulkan12Features v12{};
    VkPhysicalDeviceDynamicRenderingFeatures dynamic_rendering{};
    VkPhysicalDeviceSynchronization2Features synchronization2{};
    VkPhysicalDeviceExtendedDynamicStateFeaturesEXT extended_dynamic_state{};

    FeatureChain();  // links the pNext chain: base -> v12 -> dynamic_rendering -> ...
    FeatureChain(const FeatureChain&) = delete;
    FeatureChain& operator=(const FeatureChain&) = delete;
};

// True when the device offers the extension `name`.
bool has_device_extension(VkPhysicalDevice device, const char* name);
// True when the device offers every extension in kPromotedExtensions.
bool has_promoted_extensions(VkPhysicalDevice device);

}  // namespace ds::vk
