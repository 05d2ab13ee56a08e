#include "renderer/view/readout.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "renderer/format/format.h"
#include "renderer/view/decode.h"
#include "renderer/view/pixel.h"

namespace ds::view {
namespace {

using graph::Semantic;

template <typename... Args>
std::string text(const char* fmt, Args... args) {
    char buf[160];
    int n = std::snprintf(buf, sizeof buf, fmt, args...);
    if (n < 0) return {};
    return std::string(buf, size_t(std::min(n, int(sizeof buf) - 1)));
}

std::string tuple_text(const float* v, uint32_t n, const char* fmt) {
    std::string s = "(";
    for (uint32_t i = 0; i < n; ++i) {
        if (i) s += ", ";
        s += text(fmt, double(v[i]));
    }
    return s + ")";
}

const char* scalar_label(const std::string& name) {
    if (name.find("rough") != std::string::npos) return "roughness";
    if (name.find("shadow") != std::string::npos) return "shadow";
    return "value";
}

// --- One function per kind of texel (r.raw and r.channels already filled) -----------------

void perspective_depth_text(const InspectedImage& image, Readout& r) {
    const float v = r.raw[0];
    const bool reverse = image.semantic == Semantic::ReverseZDepth;
    r.raw_text = text("%.7f", double(v));
    if (is_sky_depth(v, reverse)) {
        r.sky = true;
        r.decoded_text = "sky (far plane)";
    } else {
        float d = linear_depth(v, reverse, image.znear, image.zfar);
        r.linear_depth = d;
        r.decoded_text = text("linear depth %.3f (scene units)", double(d));
    }
}

void normal_text(Readout& r) {
    r.raw_text = tuple_text(r.raw.data(), r.channels, "%.3f");
    std::array<float, 3> n{r.raw[0] * 2.0f - 1.0f, r.raw[1] * 2.0f - 1.0f, r.raw[2] * 2.0f - 1.0f};
    float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (len > 1e-6f && std::isfinite(len)) {
        for (float& c : n) c /= len;
        r.normal = n;
        r.decoded_text = "normal " + tuple_text(n.data(), 3, "%.2f");
    } else {
        r.decoded_text = "normal (none: zero vector)";
    }
}

void colour_text(const InspectedImage& image, Readout& r) {
    r.raw_text = tuple_text(r.raw.data(), r.channels, "%.3f");
    if (image.semantic == Semantic::HdrColor) {
        float lum = 0.2126f * r.raw[0] + 0.7152f * r.raw[1] + 0.0722f * r.raw[2];
        r.decoded_text = "linear rgb " + tuple_text(r.raw.data(), 3, "%.3f") +
                         text(", luminance %.3f", double(lum));
        return;
    }
    // LdrColor: the bytes decode shows (an *_SRGB format samples as linear: encode again).
    const uint8_t* lut = detail::srgb_table();
    const bool srgb = format::is_srgb(image.format);
    auto byte = [&](float c) { return int(srgb ? detail::srgb8(lut, c) : detail::unorm8(c)); };
    r.decoded_text = text("sRGB 8-bit (%d, %d, %d), alpha %.3f", byte(r.raw[0]), byte(r.raw[1]),
                          byte(r.raw[2]), double(r.raw[3]));
}

void describe(const InspectedImage& image, Readout& r) {
    const float v = r.raw[0];
    switch (image.semantic) {
        case Semantic::ReverseZDepth:
        case Semantic::ForwardZDepth:
            perspective_depth_text(image, r);
            break;
        case Semantic::ShadowDepth:
            r.raw_text = text("%.7f", double(v));
            r.decoded_text = text("shadow depth %.5f (orthographic, raw)", double(v));
            break;
        case Semantic::EncodedNormal:
            normal_text(r);
            break;
        case Semantic::UnormScalar:
            r.raw_text = text("%.3f", double(v));
            r.decoded_text = text("%s %.3f", scalar_label(image.name), double(v));
            break;
        case Semantic::AO:
            r.raw_text = text("%.3f", double(v));
            r.decoded_text = text("AO %.3f", double(v));
            break;
        case Semantic::HdrColor:
        case Semantic::LdrColor:
            colour_text(image, r);
            break;
        case Semantic::DepthStep:
            r.raw_text = tuple_text(r.raw.data(), 2, "%.4g");
            r.decoded_text = v > 0.0f
                                 ? "one step = " + length_text(v) + " at " + length_text(r.raw[1])
                                 : std::string("nothing drawn");
            break;
        case Semantic::SurfaceId:
            r.raw_text = text("%.0f", double(v));
            r.decoded_text =
                v == 0.0f ? std::string("no surface") : text("surface %.0f", double(v));
            break;
        case Semantic::Count:
            r.raw_text = text("%.0f", double(v));
            r.decoded_text = text("%.0f %s", double(v), v == 1.0f ? "fragment" : "fragments");
            break;
        case Semantic::Other:
            r.raw_text = r.channels == 1 ? text("%.5g", double(v))
                                         : tuple_text(r.raw.data(), r.channels, "%.5g");
            break;
        case Semantic::Scalar:
            r.raw_text = text("%.5g", double(v));
            r.decoded_text = hover_text(image.display.hover, v);
            break;
    }
}

}  // namespace

std::string length_text(float metres) {
    const double m = metres;
    if (m < 1e-4) return text("%.3g um", m * 1e6);
    if (m < 1.0) return text("%.3g mm", m * 1e3);
    if (m < 1e3) return text("%.3g m", m);
    return text("%.3g km", m * 1e-3);
}

std::string value_text(float value) {
    const std::string s = text("%.3g", double(value));
    const double rounded = std::abs(std::strtod(s.c_str(), nullptr));
    if (s.find('e') == std::string::npos || rounded < 1e3 || rounded >= 1e6) return s;
    return text("%.0f", std::strtod(s.c_str(), nullptr));  // "1.23e+03" -> "1230"
}

std::string hover_text(std::string_view format, float value) {
    const std::string number = value_text(value);
    std::string out;
    for (size_t i = 0; i < format.size(); ++i) {
        if (format.compare(i, 2, "{}") == 0) {
            out += number;
            ++i;
        } else {
            out += format[i];
        }
    }
    return out;
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
    describe(image, r);
    return r;
}

}  // namespace ds::view
