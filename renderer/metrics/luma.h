#pragma once
// Luma of 8-bit sRGB-encoded colour and the errors measured on it: a per-pixel absolute error
// map and the mean error over masked pixels (edges).
#include <cstdint>
#include <vector>

#include "renderer/metrics/image.h"

namespace ds::metrics {

// Y = 0.2126 R + 0.7152 G + 0.0722 B (Rec. 709 weights) on the 0..255 code values as they
// are stored, without linearising (as image-quality tools take luma of sRGB files); alpha is
// ignored. Throws ds::Error when the buffer does not hold width * height * 4 bytes.
LumaImage luma(const Rgba8View& image);

// |a - b| per pixel. Throws ds::Error for images of different sizes.
LumaImage abs_difference(const LumaImage& a, const LumaImage& b);

// The mean |a - b| over the pixels a mask selects.
struct MaskedError {
    uint64_t pixels = 0;  // how many the mask selected
    double mean = 0;      // NaN when `pixels` is 0: there is no error to average
};

// Edge error: `mask` (one bool per pixel, top row first; typically the pixels on edges) selects
// where |a - b| is averaged. Throws ds::Error for images of different sizes or a mask of
// another size.
MaskedError edge_error(const LumaImage& a, const LumaImage& b, const std::vector<bool>& mask);

}  // namespace ds::metrics
