#include "renderer/graph/types.h"

#include <algorithm>

namespace ds::graph {

VkExtent2D ImageSize::resolve(VkExtent2D output) const {
    if (!is_relative()) return absolute;
    auto scaled = [&](uint32_t v) { return std::max(1u, uint32_t(float(v) * scale)); };
    return {scaled(output.width), scaled(output.height)};
}

}  // namespace ds::graph
