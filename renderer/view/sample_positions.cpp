#include "renderer/view/sample_positions.h"

namespace ds::view {
namespace {

// Vulkan 1.3 spec, table "Standard sample locations" (the D3D patterns: n/16 + 0.5 offsets).
constexpr SamplePosition kOne[] = {{0.5f, 0.5f}};
constexpr SamplePosition kTwo[] = {{0.75f, 0.75f}, {0.25f, 0.25f}};
constexpr SamplePosition kFour[] = {
    {0.375f, 0.125f}, {0.875f, 0.375f}, {0.125f, 0.625f}, {0.625f, 0.875f}};
constexpr SamplePosition kEight[] = {{0.5625f, 0.3125f}, {0.4375f, 0.6875f}, {0.8125f, 0.5625f},
                                     {0.3125f, 0.1875f}, {0.1875f, 0.8125f}, {0.0625f, 0.4375f},
                                     {0.6875f, 0.9375f}, {0.9375f, 0.0625f}};
constexpr SamplePosition kSixteen[] = {
    {0.5625f, 0.5625f}, {0.4375f, 0.3125f}, {0.3125f, 0.625f},  {0.75f, 0.4375f},
    {0.1875f, 0.375f},  {0.625f, 0.8125f},  {0.8125f, 0.6875f}, {0.6875f, 0.1875f},
    {0.375f, 0.875f},   {0.5f, 0.0625f},    {0.25f, 0.125f},    {0.125f, 0.75f},
    {0.0f, 0.5f},       {0.9375f, 0.25f},   {0.875f, 0.9375f},  {0.0625f, 0.0f}};

}  // namespace

std::span<const SamplePosition> standard_sample_positions(uint32_t samples) {
    switch (samples) {
        case 1:
            return kOne;
        case 2:
            return kTwo;
        case 4:
            return kFour;
        case 8:
            return kEight;
        case 16:
            return kSixteen;
        default:
            return {};
    }
}

}  // namespace ds::view
