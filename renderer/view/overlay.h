#pragma once
// What the viewer builds from several images at once: count images grouped by pass (so one
// heat scale and one legend can serve them all), the derived "wasted" view, and overlays
// blended over a decoded view. Pure functions, like decode.h: no Vulkan calls, no ImGui.
//
// Count images are known by name alone: "<pass>_<kind>", kind one of kCountKinds ("counts"
// is what the pass shaded). The pass is everything before the last '_', so no pass name is
// written down here ("depth_prepass_discarded" is depth_prepass's).
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "renderer/view/decode.h"
#include "renderer/view/image.h"

namespace ds::view {

// In the order a viewer lists a pass's images; "wasted" is derived (wasted_image), never a
// graph resource. Fragments per pixel all: `<pass>_quads` (quads per 2x2 block, half size) is
// another unit and keeps a scale of its own.
inline constexpr std::array<std::string_view, 4> kCountKinds{"counts", "discarded", "rasterized",
                                                             "wasted"};
inline constexpr std::string_view kShadedKind = "counts";
inline constexpr std::string_view kWastedKind = "wasted";

struct CountImageName {
    std::string pass, kind;
};
// "<pass>_<kind>" split at its last '_'; none when the kind is not a count kind or the pass
// part is empty.
std::optional<CountImageName> count_image_name(std::string_view image);
inline std::string count_image(std::string_view pass, std::string_view kind) {
    return std::string(pass) + "_" + std::string(kind);
}

// A counting pass's wasted fragments per pixel: max(shaded - covered, 0), covered = 1 where
// `depth` (the frame's resolved scene depth) is not at the far value — the pixels
// FrameResult::covered_pixels counts. A Count image named "<pass>_wasted" (from
// `shaded`'s name); none when `shaded` is no "<pass>_counts" Count image, `depth` is no perspective
// depth, or the sizes differ.
std::optional<InspectedImage> wasted_image(const InspectedImage& shaded,
                                           const InspectedImage& depth);

// The largest finite count (r) over `images` (0 when there is none): the top of a heat scale
// shared by images that must show the same number in the same colour.
float count_max(std::span<const InspectedImage* const> images);

// `over` (8 bits) blended onto `base` with `opacity` (0..1): base + (over - base) * opacity,
// rounded to nearest.
inline uint8_t blend8(uint8_t base, uint8_t over, float opacity) {
    const float v = float(base) + (float(over) - float(base)) * opacity;
    return uint8_t(std::min(std::max(v, 0.0f), 255.0f) + 0.5f);
}

// Blends `colours` (the overlay as decode shows it) over `base` with `opacity`, texel by
// texel, where `values` (the overlay as read) has a non-zero r: nothing counted there is
// transparent. Returns false, changing nothing, when the three sizes differ.
bool blend_overlay(DecodedView& base, const DecodedView& colours, const InspectedImage& values,
                   float opacity);

}  // namespace ds::view
