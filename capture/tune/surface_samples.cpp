#include "capture/tune/surface_samples.h"

#include <limits>
#include <unordered_map>

#include "renderer/common/error.h"

namespace ds::tune {
namespace {

struct SampleFacts {
    int32_t material = kNoMaterial;
    uint64_t surface = std::numeric_limits<uint64_t>::max();  // nothing
};

// Surface ids seen repeatedly across a frame: each described once.
class SurfaceCache {
  public:
    SurfaceCache(const scene::Scene& scene, const DescribeSurface& describe)
        : scene_(scene), describe_(describe) {}
    SampleFacts operator()(float texel) {
        const auto id = uint32_t(texel);  // the inspect pass reads u32 ids as floats (< 2^24)
        if (id == 0) return {};
        auto it = cache_.find(id);
        if (it != cache_.end()) return it->second;
        SampleFacts f;
        if (const std::optional<SurfaceInfo> info = describe_(id)) {
            const scene::Material& m = scene_.instance_material(info->instance);
            f.material = int32_t(&m - scene_.materials.data());
            const bool masked = m.alpha_mode == scene::AlphaMode::Mask;
            f.surface = (uint64_t(info->instance) << 32) | (masked ? info->triangle : 0xffffffffu);
        }
        return cache_.emplace(id, f).first->second;
    }

  private:
    const scene::Scene& scene_;
    const DescribeSurface& describe_;
    std::unordered_map<uint32_t, SampleFacts> cache_;
};

// Fills pixel p's samples from `at(k)` (the k-th sample's texel) and its edge flag.
template <class At>
void fill_pixel(SurfaceSamples& s, size_t p, SurfaceCache& cache, At at) {
    uint64_t first = 0;
    bool edge = false;
    for (uint32_t k = 0; k < s.per_pixel; ++k) {
        const SampleFacts f = cache(at(k));
        s.material[p * s.per_pixel + k] = f.material;
        if (k == 0) first = f.surface;
        edge = edge || f.surface != first;
    }
    s.edges[p] = edge ? 1 : 0;
}

SurfaceSamples sized(uint32_t width, uint32_t height, uint32_t per_pixel) {
    SurfaceSamples s;
    s.width = width;
    s.height = height;
    s.per_pixel = per_pixel;
    s.material.assign(size_t(width) * height * per_pixel, kNoMaterial);
    s.edges.assign(size_t(width) * height, 0);
    return s;
}

}  // namespace

SurfaceSamples samples_from_blocks(const InspectedImage& ids, uint32_t factor,
                                   const scene::Scene& scene, const DescribeSurface& describe) {
    if (factor == 0 || ids.width % factor || ids.height % factor ||
        ids.texels.size() != size_t(ids.width) * ids.height * 4)
        throw Error("tune: surface ids of " + std::to_string(ids.width) + "x" +
                    std::to_string(ids.height) + " are no whole blocks of " +
                    std::to_string(factor));
    SurfaceSamples s = sized(ids.width / factor, ids.height / factor, factor * factor);
    SurfaceCache cache(scene, describe);
    for (uint32_t y = 0; y < s.height; ++y)
        for (uint32_t x = 0; x < s.width; ++x)
            fill_pixel(s, size_t(y) * s.width + x, cache, [&](uint32_t k) {
                const size_t sx = size_t(x) * factor + k % factor;
                const size_t sy = size_t(y) * factor + k / factor;
                return ids.texels[(sy * ids.width + sx) * 4];
            });
    return s;
}

SurfaceSamples samples_from_layers(const std::vector<const InspectedImage*>& ids,
                                   const scene::Scene& scene, const DescribeSurface& describe) {
    if (ids.empty() || !ids.front()) throw Error("tune: no surface-id images");
    const uint32_t w = ids.front()->width, h = ids.front()->height;
    for (const InspectedImage* i : ids)
        if (!i || i->width != w || i->height != h || i->texels.size() != size_t(w) * h * 4)
            throw Error("tune: the surface-id samples differ in size");
    SurfaceSamples s = sized(w, h, uint32_t(ids.size()));
    SurfaceCache cache(scene, describe);
    for (size_t p = 0; p < size_t(w) * h; ++p)
        fill_pixel(s, p, cache, [&](uint32_t k) { return ids[k]->texels[p * 4]; });
    return s;
}

std::vector<float> material_coverage(const SurfaceSamples& s, int32_t material) {
    std::vector<float> out(size_t(s.width) * s.height, 0.0f);
    if (s.empty()) return out;
    for (size_t p = 0; p < out.size(); ++p) {
        uint32_t n = 0;
        for (uint32_t k = 0; k < s.per_pixel; ++k) n += s.material[p * s.per_pixel + k] == material;
        out[p] = float(n) / float(s.per_pixel);
    }
    return out;
}

}  // namespace ds::tune
