#include "capture/tune/reference.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "renderer/common/error.h"

namespace ds::tune {
namespace {

float aces_fitted(float x) {
    const float a = 2.51f, b = 0.03f, c = 2.43f, d = 0.59f, e = 0.14f;
    return std::clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0f, 1.0f);
}

uint8_t srgb8(float linear) {
    const float v =
        linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
    return uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

Settings reference_settings(const Settings& settings) {
    Settings s = scored_settings(settings);
    s.set("msaa", "1");
    s.set("sample_shading", "off");
    s.set("alpha_to_coverage", "off");
    s.set("alpha_level0", "on");
    s.set("surface_id", "on");
    return s;
}

// The factor x factor block average of a factor-times-larger RGBA image, in linear HDR.
std::vector<float> box_resolve(const InspectedImage& big, uint32_t factor, uint32_t w, uint32_t h) {
    std::vector<float> out(size_t(w) * h * 4, 0.0f);
    const float weight = 1.0f / float(factor * factor);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            double sum[4] = {0, 0, 0, 0};
            for (uint32_t sy = 0; sy < factor; ++sy)
                for (uint32_t sx = 0; sx < factor; ++sx) {
                    const size_t i =
                        ((size_t(y) * factor + sy) * big.width + size_t(x) * factor + sx) * 4;
                    for (int c = 0; c < 4; ++c) sum[c] += big.texels[i + c];
                }
            for (int c = 0; c < 4; ++c) out[(size_t(y) * w + x) * 4 + c] = float(sum[c]) * weight;
        }
    return out;
}

}  // namespace

Settings scored_settings(const Settings& settings) {
    Settings s = settings;
    s.set("gtao", "off");
    s.set("contact_shadows", "off");
    return s;
}

void tonemap_rgba8(const float* hdr_rgba, float exposure, uint8_t* out_rgba) {
    for (int c = 0; c < 3; ++c)
        out_rgba[c] = srgb8(aces_fitted(std::max(hdr_rgba[c], 0.0f) * exposure));
    out_rgba[3] = 255;
}

Reference render_reference(Renderer& renderer, const scene::Scene& scene,
                           const scene::Camera& camera, const Settings& settings, VkExtent2D size) {
    const auto start = std::chrono::steady_clock::now();
    Reference ref;
    ref.width = size.width;
    ref.height = size.height;
    const Settings s = reference_settings(settings);
    RenderRequest request{.width = size.width * ref.factor, .height = size.height * ref.factor};
    request.read_back = ReadBack::Color;
    request.inspect = {{"hdr"}, {"surface_id"}};
    const FrameResult frame = renderer.render(camera, s, request);
    const InspectedImage* hdr = frame.image("hdr");
    if (!hdr || hdr->texels.size() != size_t(request.width) * request.height * 4)
        throw Error("tune: the reference frame has no HDR image to resolve");
    ref.hdr = box_resolve(*hdr, ref.factor, ref.width, ref.height);
    ref.readback_bytes = hdr->texels.size() * sizeof(float);
    const float exposure = s.get_float("exposure");
    ref.rgba8.resize(size_t(ref.width) * ref.height * 4);
    for (size_t p = 0; p < size_t(ref.width) * ref.height; ++p)
        tonemap_rgba8(&ref.hdr[p * 4], exposure, &ref.rgba8[p * 4]);
    if (const InspectedImage* ids = frame.image("surface_id")) {
        ref.samples = samples_from_blocks(
            *ids, ref.factor, scene, [&](uint32_t id) { return renderer.describe_surface(id); });
        ref.edges = ref.samples.edges;
        ref.readback_bytes += ids->texels.size() * sizeof(float);
    }
    ref.ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return ref;
}

}  // namespace ds::tune
