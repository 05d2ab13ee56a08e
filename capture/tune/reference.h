#pragma once
// The ground truth that tuning is scored against (issue 30): the same camera, scene and
// settings rendered at kReferenceFactor x kReferenceFactor samples per pixel, every sample
// shaded (the frame at that many times the size, msaa 1), alpha-tested materials sampling
// their texture's level 0 (alpha_level0), resolved with a box filter in linear HDR, then
// exposed, tonemapped and sRGB-encoded on the host exactly as shaders/tonemap.frag does.
// gtao (with ao_spatial and ao_temporal) and contact_shadows are off here and in every frame
// scored against it (scored_settings), so a score measures antialiasing, not AO.
//
// Its samples' surfaces (the prepass's surface ids) say which pixels are edges (their samples
// see more than one surface; a masked surface counts per triangle, so a pixel straddling an
// alpha cutoff over the same plant counts too) and how much of each pixel each material covers.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "capture/tune/surface_samples.h"
#include "renderer/renderer.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings.h"

namespace ds::tune {

inline constexpr uint32_t kReferenceFactor = 4;  // samples per pixel: 4 x 4

// `settings` with what a score must not measure turned off: gtao (ao_spatial, ao_temporal
// follow it) and contact_shadows.
Settings scored_settings(const Settings& settings);

struct Reference {
    uint32_t width = 0, height = 0;
    uint32_t factor = kReferenceFactor;
    std::vector<uint8_t> rgba8;  // the resolved, tonemapped image (final.png's encoding)
    std::vector<float> hdr;      // the box-resolved linear HDR colour, RGBA, before exposure
    // Per pixel, its factor² samples' surfaces (empty without the prepass: no surface ids).
    SurfaceSamples samples;
    std::vector<uint8_t> edges;   // per pixel 1: an edge (see above); empty without samples
    double ms = 0;                // wall time of the whole reference (render, read back, resolve)
    uint64_t readback_bytes = 0;  // host memory the read-back images took
};

// Renders the reference of `camera`'s view at `size` (Renderer::set_scene(scene) done).
// Throws what Renderer::render throws (a size over the device's limit at factor times it).
Reference render_reference(Renderer& renderer, const scene::Scene& scene,
                           const scene::Camera& camera, const Settings& settings, VkExtent2D size);

// shaders/common/tonemap.glsl on the host: exposure, Narkowicz's ACES fit, then the sRGB
// encoding the _SRGB final target applies, rounded to 8 bits.
void tonemap_rgba8(const float* hdr_rgba, float exposure, uint8_t* out_rgba);

}  // namespace ds::tune
