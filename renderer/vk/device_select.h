#pragma once
// Device selection as a pure function over candidate descriptions, so the rules (and their
// error messages) are unit-tested without a Vulkan device.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ds::vk {

// What selection needs to know about one physical device (filled from Vulkan by the context).
struct DeviceCandidate {
    uint32_t index = 0;  // position in vkEnumeratePhysicalDevices order
    std::string name;
    std::string type;          // "cpu", "discrete-gpu", ...
    uint32_t api_version = 0;  // VK_MAKE_API_VERSION
    // A Vulkan 1.2 device that offers the 1.3 features we need as extensions
    // (VK_KHR_dynamic_rendering, VK_KHR_synchronization2, VK_EXT_extended_dynamic_state). This is
    // what lavapipe looks like under RenderDoc, which hides 1.3 when the device lacks
    // bufferDeviceAddressCaptureReplay.
    bool via_extensions = false;
    bool dynamic_rendering = false;
    bool synchronization2 = false;
    bool extended_dynamic_state = false;  // core in 1.3 but a feature query costs nothing
    bool graphics_compute_queue = false;  // one family with both GRAPHICS and COMPUTE
};

// Reasons the candidate cannot be used; empty when it meets every requirement.
std::vector<std::string> unmet_requirements(const DeviceCandidate& candidate);

// Picks a device. `request`: "" = first device that meets the requirements; digits = that
// index; anything else = first suitable device whose name contains it (case-insensitive).
// Throws ds::Error naming every device and why it was refused.
uint32_t select_device(const std::vector<DeviceCandidate>& candidates, std::string_view request);

// "0: llvmpipe (LLVM 15.0.6, 256 bits) [cpu, Vulkan 1.3.230]" (+ "; refused: ..." if unmet).
std::string describe_candidate(const DeviceCandidate& candidate);

}  // namespace ds::vk
