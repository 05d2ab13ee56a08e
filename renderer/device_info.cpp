#include "renderer/device_info.h"

#include <cstdint>

#include "renderer/common/error.h"
#include "renderer/renderer.h"
#include "renderer/vk/capabilities.h"

namespace ds {

DeviceInfo device_info(const Renderer& renderer) {
    const vk::DeviceReport& d = renderer.device_report();
    return {.name = d.candidate.name,
            .driver = d.driver_name + " " + d.driver_info,
            .api_version = vk::version_string(d.candidate.api_version)};
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
