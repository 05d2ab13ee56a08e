#pragma once
// The device's capabilities as plain data and text, for app/ (which has no Vulkan): the facts
// report.json names, and the listing `depthscope info` prints.
#include <string>
#include <vector>

#include "renderer/common/device_info.h"

namespace ds {

class Renderer;

// The renderer's device, as report.json names it.
DeviceInfo device_info(const Renderer& renderer);

// One device as `depthscope info` lists it.
struct ListedDevice {
    std::string description;  // multi-line, ends with a newline
    bool selected = false;    // the one a renderer given the same request would use
};
// Every device, probed on a private instance (no validation), in enumeration order. With no
// suitable device each still comes back (its description says why it was refused); a
// non-empty `request` (as RendererOptions::device) that matches nothing throws ds::Error.
std::vector<ListedDevice> list_devices(const std::string& request);

}  // namespace ds
