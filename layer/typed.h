#pragma once
// A zeroed Vulkan structure with its sType set.
#include <vulkan/vulkan.h>

namespace ds::layer {

template <typename T>
T typed(VkStructureType type) {
    T s{};
    s.sType = type;
    return s;
}

}  // namespace ds::layer
