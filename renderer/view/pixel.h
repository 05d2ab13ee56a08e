#pragma once
// Internal to the view library (decode.cpp, heat.cpp, readout.cpp): the 8-bit encodes, the
// look-up tables and the black..white range they share, so the image decode, the legend and
// the readout turn a value into the same byte. Not for callers outside renderer/view.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "renderer/graph/display.h"

namespace ds::view::detail {

using Rgb = std::array<uint8_t, 3>;

// Linear 0..1 -> sRGB-encoded 8 bits, indexed by round(v * (kSrgbLutSize - 1)). 16K entries
// keep the dark end (slope 12.92) within rounding of the exact encode.
inline constexpr int kSrgbLutSize = 16384;
const uint8_t* srgb_table();  // built once (decode.cpp)

// Entry 0 is black (t <= 0); entries 1..256 are the heat map at (i - 1) / 255, so the
// smallest count above black is already blue.
inline constexpr int kHeatLutSize = 257;
const Rgb* heat_table();  // built once (heat.cpp)

inline float clamp01(float v) {
    return std::min(std::max(v, 0.0f), 1.0f);
}
inline uint8_t unorm8(float v) {
    return uint8_t(clamp01(v) * 255.0f + 0.5f);
}
inline uint8_t srgb8(const uint8_t* lut, float linear) {
    return lut[int(clamp01(linear) * float(kSrgbLutSize - 1) + 0.5f)];
}
inline int heat_index(float t) {  // t already through Range::t
    return t > 0.0f ? 1 + int(std::min(t, 1.0f) * 255.0f + 0.5f) : 0;
}

// black..white as t = (v - black) * scale + bias; see decode.h for the degenerate cases.
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

// A Scalar image's shown quantity (graph/display.h): v, or log10 v (NaN for v <= 0).
inline float scalar_shown(graph::ValueScale scale, float v) {
    if (scale == graph::ValueScale::Linear) return v;
    return v > 0.0f ? std::log10(v) : std::numeric_limits<float>::quiet_NaN();
}
// A black..white range in the value's unit as the range over the shown quantity (Log: values
// at or below 0 count as 1e-30).
inline Range scalar_range(graph::ValueScale scale, float black, float white) {
    if (scale == graph::ValueScale::Linear) return Range::manual(black, white);
    return Range::manual(std::log10(std::max(black, 1e-30f)), std::log10(std::max(white, 1e-30f)));
}
// The colour of a finite value `v` of a Scalar image over `r` (the shown quantity's range):
// decode and the legend both come here, so the legend matches the pixels.
inline Rgb scalar_rgb(const graph::Display& d, const Range& r, float v) {
    const bool log = d.scale == graph::ValueScale::Log;
    if (log && !(v > 0.0f)) return {0, 0, 0};  // no log: nothing to show
    const float t = r.t(log ? std::log10(v) : v);
    if (d.palette == graph::Palette::Grey) {
        const uint8_t g = unorm8(t);
        return {g, g, g};
    }
    const int i = heat_index(t);
    return heat_table()[log ? std::max(i, 1) : i];  // Log: only "no value" is black
}

}  // namespace ds::view::detail
