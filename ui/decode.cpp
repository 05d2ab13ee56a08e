#include "ui/decode.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

namespace ds::ui {

namespace {

using graph::Semantic;
using Rgb = std::array<uint8_t, 3>;

// --- Look-up tables (built once, read-only afterwards) -------------------------------------

// Linear 0..1 -> sRGB-encoded 8 bits, indexed by round(v * (kSrgbLutSize - 1)). 16K entries
// keep the dark end (slope 12.92) within rounding of the exact encode.
constexpr int kSrgbLutSize = 16384;

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

const uint8_t* srgb_table() {
    static const SrgbLut lut;
    return lut.table.data();
}

// The heat map's stops, t = 0+ .. 1 (t <= 0 is black).
constexpr std::array<Rgb, 6> kHeatStops{{
    {0, 40, 255},     // blue
    {0, 220, 255},    // cyan
    {0, 210, 40},     // green
    {255, 230, 0},    // yellow
    {235, 20, 0},     // red
    {255, 255, 255},  // white
}};

Rgb heat_exact(float t) {
    if (!(t > 0.0f)) return {0, 0, 0};
    t = std::min(t, 1.0f);
    float x = t * float(kHeatStops.size() - 1);
    size_t i = std::min(size_t(x), kHeatStops.size() - 2);
    float f = x - float(i);
    Rgb out{};
    for (size_t c = 0; c < 3; ++c) {
        float a = kHeatStops[i][c], b = kHeatStops[i + 1][c];
        out[c] = uint8_t(a + (b - a) * f + 0.5f);
    }
    return out;
}

// Entry 0 is black (t <= 0); entries 1..256 are the heat map at (i - 1) / 255, so the
// smallest count above black is already blue.
constexpr int kHeatLutSize = 257;

struct HeatLut {
    std::array<Rgb, kHeatLutSize> table{};
    HeatLut() {
        table[0] = {0, 0, 0};
        for (int i = 1; i < kHeatLutSize; ++i) {
            // A tiny positive t for the first entry: the palette's first stop, not black.
            float t = std::max(float(i - 1) / 255.0f, std::numeric_limits<float>::min());
            table[size_t(i)] = heat_exact(t);
        }
    }
};

const Rgb* heat_table() {
    static const HeatLut lut;
    return lut.table.data();
}

// --- Per-texel helpers ---------------------------------------------------------------------

inline float clamp01(float v) {
    return std::min(std::max(v, 0.0f), 1.0f);
}
inline uint8_t unorm8(float v) {
    return uint8_t(clamp01(v) * 255.0f + 0.5f);
}
inline uint8_t srgb8(const uint8_t* lut, float linear) {
    return lut[int(clamp01(linear) * float(kSrgbLutSize - 1) + 0.5f)];
}
inline int heat_index(float t) {  // t already through Range::apply_unclamped
    return t > 0.0f ? 1 + int(std::min(t, 1.0f) * 255.0f + 0.5f) : 0;
}
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

// black..white as t = (v - black) * scale + bias; see the header for the degenerate cases.
struct Range {
    float black = 0, white = 1, scale = 1, bias = 0;

    static Range manual(float black, float white) {
        Range r{black, white, 0, 0};
        if (white != black) {
            r.scale = 1.0f / (white - black);
        } else {
            r.scale = 1e30f;  // threshold: v > black -> 1
        }
        return r;
    }
    static Range flat(float value) { return {value, value, 0.0f, 0.5f}; }

    float t(float v) const { return (v - black) * scale + bias; }
};

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

bool is_srgb_format(VkFormat format) {
    switch (format) {
        case VK_FORMAT_R8_SRGB:
        case VK_FORMAT_R8G8_SRGB:
        case VK_FORMAT_R8G8B8_SRGB:
        case VK_FORMAT_B8G8R8_SRGB:
        case VK_FORMAT_R8G8B8A8_SRGB:
        case VK_FORMAT_B8G8R8A8_SRGB:
        case VK_FORMAT_A8B8G8R8_SRGB_PACK32:
            return true;
        default:
            return false;
    }
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
    const Rgb* heat = heat_table();
    each_texel(texels, count, out, [&](const float* t, uint8_t* p) {
        float v = t[0];
        if (!std::isfinite(v)) return put(p, kNonFiniteColor);
        put(p, heat[heat_index(r.t(v))]);
    });
    view.black = r.black;
    view.white = r.white;
    view.unit = "count";
}

// Colours and normals: no range. Encode = sRGB-encode rgb (HDR, *_SRGB formats); `scale`
// multiplies rgb first (exposure). Alpha is always as stored.
template <bool Encode>
void decode_colour(const InspectedImage& image, const ViewParams& params, size_t count,
                   uint8_t* out, float scale) {
    const float* texels = image.texels.data();
    const uint8_t* lut = srgb_table();
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

// --- Readout text --------------------------------------------------------------------------

template <typename... Args>
std::string format(const char* fmt, Args... args) {
    char buf[160];
    int n = std::snprintf(buf, sizeof buf, fmt, args...);
    if (n < 0) return {};
    return std::string(buf, size_t(std::min(n, int(sizeof buf) - 1)));
}

std::string tuple_text(const float* v, uint32_t n, const char* fmt) {
    std::string s = "(";
    for (uint32_t i = 0; i < n; ++i) {
        if (i) s += ", ";
        s += format(fmt, double(v[i]));
    }
    return s + ")";
}

const char* scalar_label(const std::string& name) {
    if (name.find("rough") != std::string::npos) return "roughness";
    if (name.find("shadow") != std::string::npos) return "shadow";
    return "value";
}

}  // namespace

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

uint32_t format_channels(VkFormat format) {
    switch (format) {
        case VK_FORMAT_D16_UNORM:
        case VK_FORMAT_X8_D24_UNORM_PACK32:
        case VK_FORMAT_D32_SFLOAT:
        case VK_FORMAT_S8_UINT:
        case VK_FORMAT_D16_UNORM_S8_UINT:
        case VK_FORMAT_D24_UNORM_S8_UINT:
        case VK_FORMAT_D32_SFLOAT_S8_UINT:
        case VK_FORMAT_R8_UNORM:
        case VK_FORMAT_R8_SNORM:
        case VK_FORMAT_R8_UINT:
        case VK_FORMAT_R8_SINT:
        case VK_FORMAT_R8_SRGB:
        case VK_FORMAT_R16_UNORM:
        case VK_FORMAT_R16_SNORM:
        case VK_FORMAT_R16_UINT:
        case VK_FORMAT_R16_SINT:
        case VK_FORMAT_R16_SFLOAT:
        case VK_FORMAT_R32_UINT:
        case VK_FORMAT_R32_SINT:
        case VK_FORMAT_R32_SFLOAT:
            return 1;
        case VK_FORMAT_R8G8_UNORM:
        case VK_FORMAT_R8G8_SNORM:
        case VK_FORMAT_R8G8_UINT:
        case VK_FORMAT_R8G8_SINT:
        case VK_FORMAT_R8G8_SRGB:
        case VK_FORMAT_R16G16_UNORM:
        case VK_FORMAT_R16G16_SNORM:
        case VK_FORMAT_R16G16_UINT:
        case VK_FORMAT_R16G16_SINT:
        case VK_FORMAT_R16G16_SFLOAT:
        case VK_FORMAT_R32G32_UINT:
        case VK_FORMAT_R32G32_SINT:
        case VK_FORMAT_R32G32_SFLOAT:
            return 2;
        case VK_FORMAT_R8G8B8_UNORM:
        case VK_FORMAT_R8G8B8_SRGB:
        case VK_FORMAT_B8G8R8_UNORM:
        case VK_FORMAT_B8G8R8_SRGB:
        case VK_FORMAT_R16G16B16_SFLOAT:
        case VK_FORMAT_R32G32B32_SFLOAT:
        case VK_FORMAT_B10G11R11_UFLOAT_PACK32:
        case VK_FORMAT_E5B9G9R9_UFLOAT_PACK32:
            return 3;
        default:
            return 4;
    }
}

std::array<uint8_t, 3> heat_color(float t) {
    if (std::isnan(t)) return {0, 0, 0};
    return heat_table()[heat_index(t)];
}

std::array<uint8_t, 3> count_color(float count, float black, float white) {
    if (!std::isfinite(count)) return kNonFiniteColor;
    return heat_table()[heat_index(Range::manual(black, white).t(count))];
}

std::vector<LegendStop> count_legend(float black, float white) {
    std::vector<LegendStop> stops;
    stops.push_back({black, {0, 0, 0}});
    if (!(white > black)) return stops;
    const float span = white - black;
    const bool whole = black == std::floor(black) && white == std::floor(white);
    if (whole && span <= 8.0f) {
        for (float c = black + 1.0f; c <= white; c += 1.0f) {
            stops.push_back({c, count_color(c, black, white)});
        }
        return stops;
    }
    // The first colour above black, then five evenly spaced counts up to white (whole counts
    // when the range is whole).
    stops.push_back({whole ? black + 1.0f : black + span / 255.0f, {}});
    for (int i = 1; i <= 5; ++i) {
        float c = black + span * float(i) / 5.0f;
        stops.push_back({whole ? std::round(c) : c, {}});
    }
    for (size_t i = 1; i < stops.size(); ++i) {
        stops[i].rgb = count_color(stops[i].count, black, white);
    }
    return stops;
}

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
        case Semantic::EncodedNormal:
            decode_colour<false>(image, vp, count, p, 1.0f);
            break;
        case Semantic::LdrColor:
            if (is_srgb_format(image.format)) {
                decode_colour<true>(image, vp, count, p, 1.0f);
            } else {
                decode_colour<false>(image, vp, count, p, 1.0f);
            }
            break;
        case Semantic::HdrColor:
            decode_colour<true>(image, vp, count, p, std::exp2(params.exposure));
            break;
        case Semantic::Other:
            decode_other(image, vp, count, p, out);
            break;
    }
}

DecodedView decode(const InspectedImage& image, const ViewParams& params) {
    DecodedView view;
    decode_into(image, params, view);
    return view;
}

std::optional<Readout> readout(const InspectedImage& image, uint32_t x, uint32_t y) {
    if (x >= image.width || y >= image.height) return std::nullopt;
    const size_t index = (size_t(y) * image.width + x) * 4;
    if (image.texels.size() < index + 4) return std::nullopt;

    Readout r;
    r.x = x;
    r.y = y;
    std::copy_n(image.texels.data() + index, 4, r.raw.begin());
    r.channels = format_channels(image.format);
    const float v = r.raw[0];

    switch (image.semantic) {
        case Semantic::ReverseZDepth:
        case Semantic::ForwardZDepth: {
            const bool reverse = image.semantic == Semantic::ReverseZDepth;
            r.raw_text = format("%.7f", double(v));
            if (is_sky_depth(v, reverse)) {
                r.sky = true;
                r.decoded_text = "sky (far plane)";
            } else {
                float d = linear_depth(v, reverse, image.znear, image.zfar);
                r.linear_depth = d;
                r.decoded_text = format("linear depth %.3f (scene units)", double(d));
            }
            break;
        }
        case Semantic::ShadowDepth:
            r.raw_text = format("%.7f", double(v));
            r.decoded_text = format("shadow depth %.5f (orthographic, raw)", double(v));
            break;
        case Semantic::EncodedNormal: {
            r.raw_text = tuple_text(r.raw.data(), r.channels, "%.3f");
            std::array<float, 3> n{v * 2.0f - 1.0f, r.raw[1] * 2.0f - 1.0f, r.raw[2] * 2.0f - 1.0f};
            float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            if (len > 1e-6f && std::isfinite(len)) {
                for (float& c : n) c /= len;
                r.normal = n;
                r.decoded_text = "normal " + tuple_text(n.data(), 3, "%.2f");
            } else {
                r.decoded_text = "normal (none: zero vector)";
            }
            break;
        }
        case Semantic::UnormScalar:
            r.raw_text = format("%.3f", double(v));
            r.decoded_text = format("%s %.3f", scalar_label(image.name), double(v));
            break;
        case Semantic::AO:
            r.raw_text = format("%.3f", double(v));
            r.decoded_text = format("AO %.3f", double(v));
            break;
        case Semantic::HdrColor: {
            r.raw_text = tuple_text(r.raw.data(), r.channels, "%.3f");
            float lum = 0.2126f * v + 0.7152f * r.raw[1] + 0.0722f * r.raw[2];
            r.decoded_text = "linear rgb " + tuple_text(r.raw.data(), 3, "%.3f") +
                             format(", luminance %.3f", double(lum));
            break;
        }
        case Semantic::LdrColor: {
            r.raw_text = tuple_text(r.raw.data(), r.channels, "%.3f");
            const uint8_t* lut = srgb_table();
            bool srgb = is_srgb_format(image.format);
            auto byte = [&](float c) { return int(srgb ? srgb8(lut, c) : unorm8(c)); };
            r.decoded_text = format("sRGB 8-bit (%d, %d, %d), alpha %.3f", byte(v), byte(r.raw[1]),
                                    byte(r.raw[2]), double(r.raw[3]));
            break;
        }
        case Semantic::Count: {
            r.raw_text = format("%.0f", double(v));
            r.decoded_text = format("%.0f %s", double(v), v == 1.0f ? "fragment" : "fragments");
            break;
        }
        case Semantic::Other:
            r.raw_text = r.channels == 1 ? format("%.5g", double(v))
                                         : tuple_text(r.raw.data(), r.channels, "%.5g");
            break;
    }
    return r;
}

}  // namespace ds::ui
