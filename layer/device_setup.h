#pragma once
// Capture mode's changes at device creation: the two features counting needs
// (fragmentStoresAndAtomics for the counters, occlusionQueryPrecise for samples passed) are
// switched on where the device has them, and on a Vulkan 1.0 device the extension the
// counters' SPIR-V needs (VK_KHR_storage_buffer_storage_class), and the device's facts are noted. A device that
// cannot be captured (a feature missing, no spare descriptor set, an enabled extension with a
// command the layer does not record) keeps the application's create info exactly and says why.
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "layer/state.h"

namespace ds::layer {

class DeviceCreatePatch {
  public:
    DeviceCreatePatch(InstanceData& instance, VkPhysicalDevice physical,
                      const VkDeviceCreateInfo& info);
    ~DeviceCreatePatch();  // puts back what it changed in the application's structures
    DeviceCreatePatch(const DeviceCreatePatch&) = delete;
    DeviceCreatePatch& operator=(const DeviceCreatePatch&) = delete;

    const VkDeviceCreateInfo* info() const { return &info_; }
    const std::string& refused() const { return refused_; }

  private:
    bool enable_storage_buffer_class(InstanceData& instance, VkPhysicalDevice physical,
                                     const VkDeviceCreateInfo& info);

    VkDeviceCreateInfo info_;
    std::vector<const char*> extensions_;  // the application's, and one the layer needs
    VkPhysicalDeviceFeatures features_{};
    VkPhysicalDeviceFeatures2* chained_ = nullptr;  // the application's, changed in place
    VkPhysicalDeviceFeatures chained_before_{};
    std::string refused_;
};

// After creation: the slot, limits and memory types the capture uses.
void note_device_facts(DeviceData& device, const std::string& refused);

}  // namespace ds::layer
