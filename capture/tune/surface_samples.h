#pragma once
// What each sample of a frame saw, from the prepass's surface ids (Renderer::describe_surface):
// the material and a surface key. A surface is an instance, or for a MASK material one
// triangle of it, so that an alpha-tested card over another card of the same plant is two.
// The reference frame (reference.h) has factor x factor samples per pixel, a candidate frame
// its msaa samples.
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "renderer/renderer.h"
#include "renderer/scene/scene.h"
#include "renderer/view/image.h"

namespace ds::tune {

inline constexpr int32_t kNoMaterial = -1;  // the sample saw nothing the prepass drew (sky)

struct SurfaceSamples {
    uint32_t width = 0, height = 0;
    uint32_t per_pixel = 0;         // samples of each pixel, consecutive
    std::vector<int32_t> material;  // per sample: a Scene::materials index, or kNoMaterial
    std::vector<uint8_t> edges;     // per pixel: 1 when its samples saw more than one surface
    bool empty() const { return per_pixel == 0; }
};

// A surface-id image `factor` times the frame's size in each direction: pixel (x, y)'s samples
// are the factor x factor block at (x * factor, y * factor).
SurfaceSamples samples_from_blocks(const InspectedImage& ids, uint32_t factor,
                                   const scene::Scene& scene, const DescribeSurface& describe);
// One surface-id image per sample (msaa_surface_id read at each sample, or surface_id at msaa 1).
SurfaceSamples samples_from_layers(const std::vector<const InspectedImage*>& ids,
                                   const scene::Scene& scene, const DescribeSurface& describe);

// Per pixel, the fraction of its samples that saw `material`.
std::vector<float> material_coverage(const SurfaceSamples& s, int32_t material);

}  // namespace ds::tune
