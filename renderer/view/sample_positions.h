#pragma once
// Where a pixel's samples lie: the Vulkan spec's "Standard sample locations" table (the
// positions a device uses when VkPhysicalDeviceLimits::standardSampleLocations is true), in
// pixel units, origin at the pixel's top-left corner, y down. Sample i of the table is sample
// index i (gl_SampleID, texelFetch's sample). Pure data for the inspector's sample view.
#include <cstdint>
#include <span>

namespace ds::view {

struct SamplePosition {
    float x = 0.5f, y = 0.5f;
};

// The standard positions for `samples` (1, 2, 4, 8 or 16); empty for any other count.
std::span<const SamplePosition> standard_sample_positions(uint32_t samples);

}  // namespace ds::view
