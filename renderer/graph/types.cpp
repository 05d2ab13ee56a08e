#include "renderer/graph/types.h"

#include <algorithm>

namespace ds::graph {

VkExtent2D ImageSize::resolve(VkExtent2D output) const {
    if (!is_relative()) return absolute;
    auto scaled = [&](uint32_t v) { return std::max(1u, uint32_t(float(v) * scale)); };
    return {scaled(output.width), scaled(output.height)};
}

const char* pass_kind_name(PassKind kind) {
    switch (kind) {
        case PassKind::Graphics:
            return "graphics";
        case PassKind::Compute:
            return "compute";
        case PassKind::Transfer:
            return "transfer";
    }
    return "?";
}

const char* pass_role_name(PassRole role) {
    switch (role) {
        case PassRole::Frame:
            return "frame";
        case PassRole::Clear:
            return "clear";
        case PassRole::ReadBack:
            return "readback";
        case PassRole::Measure:
            return "measure";
        case PassRole::History:
            return "history";
    }
    return "?";
}

}  // namespace ds::graph
