#pragma once
// What a device can do, queried once (DESIGN decision 2: query, never assume), and the text
// `depthscope info` prints. Depth format choice is a pure function (seed 001) so a test can
// feed fake format properties.
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/format/format.h"
#include "renderer/vk/device_limits.h"
#include "renderer/vk/device_select.h"

namespace ds::vk {

// Most desirable first: 32-bit float depth keeps reverse-Z precision; D16 is the last resort.
// X8_D24 is listed so that depth_format=d24 finds it on devices without D24_UNORM_S8_UINT.
inline constexpr VkFormat kDepthFormatCandidates[] = {
    VK_FORMAT_D32_SFLOAT, VK_FORMAT_D32_SFLOAT_S8_UINT, VK_FORMAT_D24_UNORM_S8_UINT,
    VK_FORMAT_X8_D24_UNORM_PACK32, VK_FORMAT_D16_UNORM};

// A depth buffer is rendered to and later sampled (views, GTAO, captures).
inline constexpr VkFormatFeatureFlags kDepthFormatFeatures =
    VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT;

using FormatQuery = std::function<VkFormatProperties(VkFormat)>;

// Candidates whose optimal-tiling features include every bit of `required`, in order.
std::vector<VkFormat> supported_formats(std::span<const VkFormat> candidates,
                                        VkFormatFeatureFlags required, const FormatQuery& query);
// The first supported candidate; throws ds::Error listing the candidates when none is.
VkFormat choose_depth_format(std::span<const VkFormat> candidates, VkFormatFeatureFlags required,
                             const FormatQuery& query);

// Format facts live in the one table (renderer/format); vk::has_stencil is kept for callers.
using format::has_stencil;
std::string device_type_name(VkPhysicalDeviceType type);
std::string version_string(uint32_t api_version);
std::string sample_counts_text(VkSampleCountFlags counts);  // "1 4"
std::string resolve_modes_text(VkResolveModeFlags modes);   // "SAMPLE_ZERO AVERAGE"

struct DeviceReport {
    DeviceCandidate candidate;  // index, name, type, API version, requirement facts
    std::vector<std::string> unmet;
    uint32_t vendor_id = 0;
    uint32_t device_id = 0;
    std::string driver_name;
    std::string driver_info;
    VkDriverId driver_id = VkDriverId(0);         // 0: not reported (Vulkan 1.1 devices)
    std::vector<VkFormat> depth_formats;          // supported candidates, preference order
    VkFormat depth_format = VK_FORMAT_UNDEFINED;  // the one the renderer uses
    VkSampleCountFlags color_sample_counts = 0;
    VkSampleCountFlags depth_sample_counts = 0;
    bool standard_sample_locations = false;  // the spec's table places the samples
    VkResolveModeFlags depth_resolve_modes = 0;
    VkResolveModeFlags stencil_resolve_modes = 0;
    bool timestamps = false;  // timestampComputeAndGraphics
    float timestamp_period_ns = 0.0f;
    uint32_t timestamp_valid_bits = 0;  // of the graphics+compute queue family
    bool pipeline_statistics = false;
    bool occlusion_query_precise = false;
    bool fragment_stores_and_atomics = false;  // exact per-pixel fragment counts (count images)
    bool sample_rate_shading = false;          // sample_shading=on (per-sample forward)
    bool geometry_shader = false;      // gl_PrimitiveID in fragment shaders (surface_id, zfight)
    bool descriptor_indexing = false;  // runtimeDescriptorArray (lavapipe 22.3: no)
    // Quad subgroup operations in fragment shaders (count_fragments' quad counts).
    bool fragment_quad_operations = false;
    uint64_t device_local_bytes = 0;
    DeviceLimits limits;  // image, framebuffer, allocation and heap (DEPTHSCOPE_DEVICE_LIMITS)
    uint32_t queue_family = UINT32_MAX;  // first graphics+compute family
};

// Everything above for one device. `index` is its vkEnumeratePhysicalDevices position.
DeviceReport probe_device(VkPhysicalDevice device, uint32_t index);
// Every device on a private instance (no validation): for `depthscope info`.
std::vector<DeviceReport> probe_all_devices();
// Multi-line, human-readable; ends with a newline.
std::string format_report(const DeviceReport& report);

}  // namespace ds::vk
