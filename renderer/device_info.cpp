#include "renderer/device_info.h"

#include <cstdint>

#include "renderer/common/error.h"
#include "renderer/renderer.h"
#include "renderer/vk/capabilities.h"

namespace ds {

namespace {

// Measured, not assumed: lavapipe in this project's tests (tests/gpu/passes), NVIDIA on an
// H200 (the note of issue 11). Any other driver is described as what the spec allows.
std::string fragment_statistic_meaning(VkDriverId driver) {
    switch (driver) {
        case VK_DRIVER_ID_MESA_LLVMPIPE:
            return "lavapipe counts fragment-shader invocations once per rasterized 4x4 block, "
                   "before the depth test: it cannot show what a prepass saves "
                   "(shaded_fragments can)";
        case VK_DRIVER_ID_NVIDIA_PROPRIETARY:
            return "NVIDIA counts fragment-shader invocations after its early depth test: "
                   "where early-Z applies it equals the exact shaded_fragments (measured on "
                   "an H200), where it is lost it also counts fragments the depth test then "
                   "rejects";
        default:
            return "implementation-defined on this driver (early depth tests, helper "
                   "invocations and binning differ): compare it with shaded_fragments "
                   "(count_fragments=on)";
    }
}

}  // namespace

DeviceInfo device_info(const Renderer& renderer) {
    const vk::DeviceReport& d = renderer.device_report();
    DeviceInfo info;
    info.name = d.candidate.name;
    info.driver = d.driver_name + " " + d.driver_info;
    info.api_version = vk::version_string(d.candidate.api_version);
    info.fragment_statistic = fragment_statistic_meaning(d.driver_id);
    // As Renderer::render checks them: colour and depth attachments both.
    const VkSampleCountFlags samples = d.color_sample_counts & d.depth_sample_counts;
    for (int n = 1; n <= 8; n *= 2)
        if (samples & VkSampleCountFlags(n)) info.msaa_counts.push_back(n);
    info.standard_sample_locations = d.standard_sample_locations;
    info.fragment_counts = d.fragment_stores_and_atomics;
    info.draw_counts =
        d.fragment_stores_and_atomics && d.occlusion_query_precise && d.geometry_shader;
    info.surface_ids = d.geometry_shader;
    info.timestamps = d.timestamps && d.timestamp_valid_bits > 0;  // as the graph's profiler
    return info;
}

std::vector<ListedDevice> list_devices(const std::string& request) {
    const auto reports = vk::probe_all_devices();
    std::vector<vk::DeviceCandidate> candidates;
    for (const auto& r : reports) candidates.push_back(r.candidate);
    // The same rule the renderer uses. With no suitable device, still list them all (each says
    // why it was refused); a request that matches nothing stays an error.
    uint32_t selected = UINT32_MAX;
    try {
        selected = vk::select_device(candidates, request);
    } catch (const Error&) {
        if (!request.empty()) throw;
    }
    std::vector<ListedDevice> devices;
    for (const auto& r : reports)
        devices.push_back(
            {.description = vk::format_report(r), .selected = r.candidate.index == selected});
    return devices;
}

}  // namespace ds
