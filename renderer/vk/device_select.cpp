#include "renderer/vk/device_select.h"

#include <algorithm>
#include <cctype>
#include <charconv>

#include <vulkan/vulkan.h>

#include "renderer/common/error.h"
#include "renderer/common/quoted.h"

namespace ds::vk {
namespace {

std::string version_text(uint32_t v) {
    return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) +
           "." + std::to_string(VK_API_VERSION_PATCH(v));
}

std::string lower(std::string_view s) {
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return out;
}

std::string join(const std::vector<std::string>& parts, const char* sep) {
    std::string out;
    for (size_t i = 0; i < parts.size(); ++i) out += (i ? sep : "") + parts[i];
    return out;
}

std::string device_list(const std::vector<DeviceCandidate>& candidates) {
    if (candidates.empty()) return " (no Vulkan devices were found)";
    // One line: errors are printed as a single `depthscope: error: ...` line.
    std::string out;
    for (const DeviceCandidate& c : candidates) {
        out += (out.empty() ? " " : " | ") + describe_candidate(c);
    }
    return out;
}

bool is_index(std::string_view s) {
    return !s.empty() &&
           std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
}

}  // namespace

std::vector<std::string> unmet_requirements(const DeviceCandidate& c) {
    std::vector<std::string> out;
    if (c.api_version < VK_API_VERSION_1_2 ||
        (c.api_version < VK_API_VERSION_1_3 && !c.via_extensions))
        out.push_back("Vulkan " + version_text(c.api_version) +
                      " < 1.3 (or 1.2 with the dynamic rendering, synchronization2 and extended "
                      "dynamic state extensions)");
    if (!c.dynamic_rendering) out.push_back("no dynamicRendering");
    if (!c.synchronization2) out.push_back("no synchronization2");
    if (!c.extended_dynamic_state) out.push_back("no extendedDynamicState");
    if (!c.graphics_compute_queue) out.push_back("no graphics+compute queue");
    return out;
}

std::string describe_candidate(const DeviceCandidate& c) {
    std::string out = std::to_string(c.index) + ": " + c.name + " [" + c.type + ", Vulkan " +
                      version_text(c.api_version) + "]";
    std::vector<std::string> unmet = unmet_requirements(c);
    if (!unmet.empty()) out += "; refused: " + join(unmet, ", ");
    return out;
}

uint32_t select_device(const std::vector<DeviceCandidate>& candidates, std::string_view request) {
    if (is_index(request)) {
        uint32_t index = 0;
        const auto [ptr, ec] =
            std::from_chars(request.data(), request.data() + request.size(), index);
        if (ec != std::errc())  // too many digits for any index: no wrap-around to a real one
            throw Error("no device with index " + escaped(request) +
                        "; devices:" + device_list(candidates));
        for (const DeviceCandidate& c : candidates) {
            if (c.index != index) continue;
            std::vector<std::string> unmet = unmet_requirements(c);
            if (unmet.empty()) return c.index;
            throw Error("device " + escaped(request) + " (" + c.name +
                        ") does not meet the requirements: " + join(unmet, ", "));
        }
        throw Error("no device with index " + escaped(request) +
                    "; devices:" + device_list(candidates));
    }
    const std::string needle = lower(request);
    bool name_matched = false;
    for (const DeviceCandidate& c : candidates) {
        if (lower(c.name).find(needle) == std::string::npos) continue;
        name_matched = true;
        if (unmet_requirements(c).empty()) return c.index;
    }
    if (request.empty())
        throw Error(
            "no Vulkan device meets the requirements (Vulkan 1.3, dynamicRendering, "
            "synchronization2, extendedDynamicState, a graphics+compute queue); devices:" +
            device_list(candidates));
    throw Error(std::string(name_matched ? "no device matching '" : "no device name contains '") +
                escaped(request) + (name_matched ? "' meets the requirements" : "'") +
                "; devices:" + device_list(candidates));
}

}  // namespace ds::vk
