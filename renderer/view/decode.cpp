#include "renderer/view/decode.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "renderer/format/format.h"
#include "renderer/view/pixel.h"

namespace ds::view {

namespace {

using detail::heat_index;
using detail::kSrgbLutSize;
using detail::Range;
using detail::Rgb;
using detail::srgb8;
using detail::unorm8;
using graph::Semantic;

// --- Look-up table (built once, read-only afterwards) --------------------------------------

struct SrgbLut {
    std::array<uint8_t, kSrgbLutSize> table{};
    SrgbLut() {
        for (int i = 0; i < kSrgbLutSize; ++i) {
            double v = double(i) / (kSrgbLutSize - 1);
            double s = v <= 0.0031308 ? v * 12.92 : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
            table[size_t(i)] = uint8_t(std::clamp(s * 255.0 + 0.5, 0.0, 255.0));
        }
    }
};

// --- Per-texel helpers ---------------------------------------------------------------------

inline void put(uint8_t* p, uint8_t r, uint8_t g, uint8_t b) {
    p[0] = r;
    p[1] = g;
    p[2] = b;
    p[3] = 255;
}
inline void put(uint8_t* p, const Rgb& c) {
    put(p, c[0], c[1], c[2]);
}
inline void put_grey(uint8_t* p, uint8_t v) {
    put(p, v, v, v);
}

// Finite min/max of a quantity over the image, skipping what `get` rejects (returns NaN).
struct MinMax {
    float lo = std::numeric_limits<float>::infinity();
    float hi = -std::numeric_limits<float>::infinity();
    void add(float v) {
        if (std::isfinite(v)) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    }
    bool empty() const { return !(lo <= hi); }
};

template <typename Quantity>
MinMax fit(const float* texels, size_t count, Quantity&& quantity) {
    MinMax m;
    for (size_t i = 0; i < count; ++i) m.add(quantity(texels + 4 * i));
    return m;
}

// A manual range in scene units as the log10 range a log view fits in.
ViewParams manual_log(ViewParams p) {
    p.black = std::log10(std::max(p.black, 1e-30f));
    p.white = std::log10(std::max(p.white, 1e-30f));
    return p;
}

Range choose_range(const ViewParams& params, const MinMax& fitted, float default_black,
                   float default_white) {
    if (!params.auto_fit) return Range::manual(params.black, params.white);
    if (fitted.empty()) return Range::manual(default_black, default_white);
    if (fitted.lo == fitted.hi) return Range::flat(fitted.lo);
    return Range::manual(fitted.lo, fitted.hi);
}

template <typename Fn>
void each_texel(const float* texels, size_t count, uint8_t* out, Fn&& fn) {
    for (size_t i = 0; i < count; ++i) fn(texels + 4 * i, out + 4 * i);
}

// --- Decoders, one per kind of view --------------------------------------------------------

void decode_perspective_depth(const InspectedImage& image, const ViewParams& params, size_t count,
                              uint8_t* out, DecodedView& view) {
    const bool reverse = image.semantic == Semantic::ReverseZDepth;
    const float n = image.znear, f = image.zfar;
    const float nf = n * f, fmn = f - n;
    const float* texels = image.texels.data();
    // The sky test is written out here (not is_sky_depth) to keep the loops branch-light.
    auto sky = [reverse](float s) { return reverse ? !(s > 0.0f) : !(s < 1.0f); };
    if (params.depth == DepthView::Linear) {
        auto lin = [reverse, nf, fmn, n, f](float s) {
            return reverse ? nf / (s * fmn + n) : nf / (f - s * fmn);
        };
        MinMax m;
        if (params.auto_fit) {
            m = fit(texels, count, [&](const float* t) {
                return sky(t[0]) ? std::numeric_limits<float>::quiet_NaN() : lin(t[0]);
            });
        }
        Range r = choose_range(params, m, n, f);
        each_texel(texels, count, out, [&](const float* t, uint8_t* p) {
            float s = t[0];
            if (!std::isfinite(s)) return put(p, kNonFiniteColor);
            if (sky(s)) return put(p, kSkyColor);
            float d = lin(s);
            if (!std::isfinite(d)) return put(p, kNonFiniteColor);
            put_grey(p, unorm8(r.t(d)));
        });
        view.black = r.black;
        view.white = r.white;
        view.unit = "scene units";
    } else {
        MinMax m;
        if (params.auto_fit) {
            m = fit(texels, count, [&](const float* t) {
                return sky(t[0]) ? std::numeric_limits<float>::quiet_NaN() : t[0];
            });
        }
        Range r = choose_range(params, m, 0.0f, 1.0f);
        each_texel(texels, count, out, [&](const float* t, uint8_t* p) {
            float s = t[0];
            if (!std::isfinite(s)) return put(p, kNonFiniteColor);
            if (sky(s)) return put(p, kSkyColor);
            put_grey(p, unorm8(r.t(s)));
        });
        view.black = r.black;
        view.white = r.white;
        view.unit = "raw depth";
    }
}

// One quantity (channel `c`) as grey over the range.
void decode_grey(const InspectedImage& image, const ViewParams& params, size_t count, uint8_t* out,
                 DecodedView& view, int c) {
    const float* texels = image.texels.data();
    MinMax m;
    if (params.auto_fit) m = fit(texels, count, [c](const float* t) { return t[c]; });
    Range r = choose_range(params, m, 0.0f, 1.0f);
    each_texel(texels, count, out, [&](const float* t, uint8_t* p) {
        float v = t[c];
        if (!std::isfinite(v)) return put(p, kNonFiniteColor);
        put_grey(p, unorm8(r.t(v)));
    });
    view.black = r.black;
    view.white = r.white;
}

void decode_count(const InspectedImage& image, const ViewParams& params, size_t count, uint8_t* out,
                  DecodedView& view) {
    const float* texels = image.texels.data();
    Range r;
    if (params.auto_fit) {
        MinMax m = fit(texels, count, [](const float* t) { return t[0]; });
        r = Range::manual(0.0f, !m.empty() && m.hi > 0.0f ? m.hi : 1.0f);
    } else {
        r = Range::manual(params.black, params.white);
    }
    const Rgb* heat = detail::heat_table();
    each_texel(texels, count, out, [&](const float* t, uint8_t* p) {
        float v = t[0];
        if (!std::isfinite(v)) return put(p, kNonFiniteColor);
        put(p, heat[heat_index(r.t(v))]);
    });
    view.black = r.black;
    view.white = r.white;
    view.unit = "count";
}

// Depth steps: r on a log scale (the range in scene units, fitted in log10), as the heat map;
// nothing drawn (0) in the sky colour.
void decode_depth_step(const InspectedImage& image, const ViewParams& params, size_t count,
                       uint8_t* out, DecodedView& view) {
    const float* texels = image.texels.data();
    auto log_step = [](const float* t) {
        return t[0] > 0.0f ? std::log10(t[0]) : std::numeric_limits<float>::quiet_NaN();
    };
    const MinMax m = fit(texels, count, log_step);
    const ViewParams logged =
        params.auto_fit ? params : manual_log(params);  // the manual range is in scene units
    const Range r = choose_range(logged, m, -6.0f, 0.0f);
    const Rgb* heat = detail::heat_table();
    each_texel(texels, count, out, [&](const float* t, uint8_t* p) {
        if (!(t[0] > 0.0f)) return put(p, kSkyColor);
        if (!std::isfinite(t[0])) return put(p, kNonFiniteColor);
        put(p, heat[std::max<size_t>(1, heat_index(r.t(std::log10(t[0]))))]);
    });
    view.black = std::pow(10.0f, r.black);
    view.white = std::pow(10.0f, r.white);
    view.unit = "scene units per depth step (log)";
}

// A Scalar image's range: `r` over the shown quantity, black and white in the value's unit.
struct ScalarRange {
    Range r;
    float black = 0.0f, white = 1.0f;
};

// The viewer's manual range, else the one the image's Display picks (graph/display.h).
ScalarRange scalar_range(const InspectedImage& image, const ViewParams& params, size_t count) {
    using Rule = graph::DisplayRange::Rule;
    const graph::Display& d = image.display;
    const graph::ValueScale scale = d.scale;
    auto manual = [scale](float black, float white) {
        return ScalarRange{detail::scalar_range(scale, black, white), black, white};
    };
    if (!params.auto_fit) return manual(params.black, params.white);
    if (d.range.rule == Rule::Fixed) return manual(d.range.black, d.range.white);
    const bool log = scale == graph::ValueScale::Log;
    // Fitted on the values (log10 keeps their order), so black and white are values read.
    const MinMax m = fit(image.texels.data(), count, [log](const float* t) {
        return log && !(t[0] > 0.0f) ? std::numeric_limits<float>::quiet_NaN() : t[0];
    });
    const float zero = log ? 1.0f : 0.0f, one = log ? 10.0f : 1.0f;  // shown 0 and 1
    if (d.range.rule == Rule::ZeroToMax)
        return manual(zero, !m.empty() && m.hi > zero ? m.hi : one);
    if (m.empty()) return manual(zero, one);
    if (m.lo == m.hi) return {Range::flat(detail::scalar_shown(scale, m.lo)), m.lo, m.hi};
    return manual(m.lo, m.hi);
}

// Scalar: r as its Display says (scale, range, palette, unit); the channel is ignored.
void decode_scalar(const InspectedImage& image, const ViewParams& params, size_t count,
                   uint8_t* out, DecodedView& view) {
    const graph::Display& d = image.display;
    const ScalarRange range = scalar_range(image, params, count);
    each_texel(image.texels.data(), count, out, [&](const float* t, uint8_t* p) {
        if (!std::isfinite(t[0])) return put(p, kNonFiniteColor);
        put(p, detail::scalar_rgb(d, range.r, t[0]));
    });
    view.black = range.black;
    view.white = range.white;
    view.unit = d.unit;
}

// Surface ids: a colour of its own per id (a hash: neighbours differ), nothing drawn in the sky
// colour. No range.
void decode_surface(const InspectedImage& image, size_t count, uint8_t* out) {
    each_texel(image.texels.data(), count, out, [&](const float* t, uint8_t* p) {
        if (!std::isfinite(t[0])) return put(p, kNonFiniteColor);
        const uint32_t id = uint32_t(t[0]);
        if (id == 0) return put(p, kSkyColor);
        put(p, surface_color(id));
    });
}

// Colours and normals: no range. Encode = sRGB-encode rgb (HDR, *_SRGB formats); `scale`
// multiplies rgb first (exposure). Alpha is always as stored.
template <bool Encode>
void decode_colour(const InspectedImage& image, const ViewParams& params, size_t count,
                   uint8_t* out, float scale) {
    const float* texels = image.texels.data();
    const uint8_t* lut = detail::srgb_table();
    auto channel8 = [lut, scale](float v) {
        if constexpr (Encode) {
            return srgb8(lut, v * scale);
        } else {
            return unorm8(v * scale);
        }
    };
    const int c = params.channel;
    if (c < 0) {
        each_texel(texels, count, out, [&](const float* t, uint8_t* p) {
            if (!std::isfinite(t[0]) || !std::isfinite(t[1]) || !std::isfinite(t[2])) {
                return put(p, kNonFiniteColor);
            }
            put(p, channel8(t[0]), channel8(t[1]), channel8(t[2]));
        });
    } else if (c == 3) {
        each_texel(texels, count, out, [&](const float* t, uint8_t* p) {
            if (!std::isfinite(t[3])) return put(p, kNonFiniteColor);
            put_grey(p, unorm8(t[3]));
        });
    } else {
        each_texel(texels, count, out, [&](const float* t, uint8_t* p) {
            if (!std::isfinite(t[c])) return put(p, kNonFiniteColor);
            put_grey(p, channel8(t[c]));
        });
    }
}

// Other: the first channels as rgb (grey for one channel) over one range for all of them.
void decode_other(const InspectedImage& image, const ViewParams& params, size_t count, uint8_t* out,
                  DecodedView& view) {
    const uint32_t channels = format_channels(image.format);
    if (params.channel >= 0 || channels == 1) {
        decode_grey(image, params, count, out, view, params.channel >= 0 ? params.channel : 0);
        return;
    }
    const float* texels = image.texels.data();
    const int shown = channels >= 3 ? 3 : 2;
    MinMax m;
    if (params.auto_fit) {
        for (size_t i = 0; i < count; ++i) {
            const float* t = texels + 4 * i;
            for (int k = 0; k < shown; ++k) m.add(t[k]);
        }
    }
    Range r = choose_range(params, m, 0.0f, 1.0f);
    each_texel(texels, count, out, [&](const float* t, uint8_t* p) {
        if (!std::isfinite(t[0]) || !std::isfinite(t[1]) || (shown == 3 && !std::isfinite(t[2]))) {
            return put(p, kNonFiniteColor);
        }
        put(p, unorm8(r.t(t[0])), unorm8(r.t(t[1])), shown == 3 ? unorm8(r.t(t[2])) : 0);
    });
    view.black = r.black;
    view.white = r.white;
}

}  // namespace

const uint8_t* detail::srgb_table() {
    static const SrgbLut lut;
    return lut.table.data();
}

// --- Public API ----------------------------------------------------------------------------

float linear_depth(float stored, bool reverse_z, float znear, float zfar) {
    const float n = znear, f = zfar;
    return reverse_z ? n * f / (stored * (f - n) + n) : n * f / (f - stored * (f - n));
}

bool is_sky_depth(float stored, bool reverse_z) {
    return reverse_z ? stored <= 0.0f : stored >= 1.0f;
}

bool is_perspective_depth(graph::Semantic semantic) {
    return semantic == Semantic::ReverseZDepth || semantic == Semantic::ForwardZDepth;
}

uint32_t format_channels(VkFormat f) {
    const format::Info* info = format::find(f);
    return info ? info->channels : 4;  // unknown: all four, as sampled
}

namespace {

// Each semantic's decoding (ViewParams::channel already checked).
void decode_semantic(const InspectedImage& image, const ViewParams& vp, size_t count, uint8_t* p,
                     DecodedView& out) {
    switch (image.semantic) {
        case Semantic::ReverseZDepth:
        case Semantic::ForwardZDepth:
            decode_perspective_depth(image, vp, count, p, out);
            break;
        case Semantic::ShadowDepth:
            decode_grey(image, vp, count, p, out, 0);
            out.unit = "raw depth";
            break;
        case Semantic::UnormScalar:
        case Semantic::AO:
            decode_grey(image, vp, count, p, out, 0);
            break;
        case Semantic::Count:
            decode_count(image, vp, count, p, out);
            break;
        case Semantic::SurfaceId:
            decode_surface(image, count, p);
            out.unit = "surface";
            break;
        case Semantic::DepthStep:
            decode_depth_step(image, vp, count, p, out);
            break;
        case Semantic::EncodedNormal:
            decode_colour<false>(image, vp, count, p, 1.0f);
            break;
        case Semantic::LdrColor:
            if (format::is_srgb(image.format)) {
                decode_colour<true>(image, vp, count, p, 1.0f);
            } else {
                decode_colour<false>(image, vp, count, p, 1.0f);
            }
            break;
        case Semantic::HdrColor:
            decode_colour<true>(image, vp, count, p, std::exp2(vp.exposure));
            break;
        case Semantic::Other:
            decode_other(image, vp, count, p, out);
            break;
        case Semantic::Scalar:
            decode_scalar(image, vp, count, p, out);
            break;
    }
}

}  // namespace

void decode_into(const InspectedImage& image, const ViewParams& params, DecodedView& out) {
    const size_t count = size_t(image.width) * image.height;
    out.black = 0.0f;
    out.white = 1.0f;
    out.unit.clear();
    if (count == 0 || image.texels.size() != count * 4) {
        out.width = out.height = 0;
        out.rgba8.clear();
        return;
    }
    out.width = image.width;
    out.height = image.height;
    out.rgba8.resize(count * 4);
    uint8_t* p = out.rgba8.data();
    const int channel = params.channel >= 0 && params.channel <= 3 ? params.channel : -1;
    ViewParams vp = params;
    vp.channel = channel;
    decode_semantic(image, vp, count, p, out);
}

void overlay_counts(DecodedView& view, const InspectedImage& counts,
                    std::span<const uint8_t> final_rgba8, float dim,
                    std::span<const uint8_t> keep) {
    const size_t texels = size_t(view.width) * view.height;
    if (counts.width != view.width || counts.height != view.height ||
        final_rgba8.size() != texels * 4 || counts.texels.size() != texels * 4 ||
        view.rgba8.size() != texels * 4 || (!keep.empty() && keep.size() != texels))
        return;
    for (size_t i = 0; i < texels; ++i) {
        if (counts.texels[i * 4] > 0.0f && (keep.empty() || keep[i])) continue;
        for (size_t c = 0; c < 3; ++c)
            view.rgba8[i * 4 + c] = uint8_t(float(final_rgba8[i * 4 + c]) * dim + 0.5f);
    }
}

void highlight(DecodedView& view, std::span<const uint8_t> keep, float dim) {
    const size_t texels = size_t(view.width) * view.height;
    if (keep.size() != texels || view.rgba8.size() != texels * 4) return;
    for (size_t i = 0; i < texels; ++i) {
        if (keep[i]) continue;
        for (size_t c = 0; c < 3; ++c)
            view.rgba8[i * 4 + c] = uint8_t(float(view.rgba8[i * 4 + c]) * dim + 0.5f);
    }
}

std::array<uint8_t, 3> surface_color(uint32_t id) {
    uint32_t h = id * 0x9e3779b9u;  // a multiplicative hash, then one xorshift round
    h ^= h >> 15;
    h *= 0x2c1b3c6du;
    h ^= h >> 12;
    // 64..255 per channel: no surface is near black or the sky colour.
    return {uint8_t(64 + (h & 0xff) * 191 / 255), uint8_t(64 + ((h >> 8) & 0xff) * 191 / 255),
            uint8_t(64 + ((h >> 16) & 0xff) * 191 / 255)};
}

DecodedView decode(const InspectedImage& image, const ViewParams& params) {
    DecodedView view;
    decode_into(image, params, view);
    return view;
}

}  // namespace ds::view
