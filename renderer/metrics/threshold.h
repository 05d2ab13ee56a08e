#pragma once
// "% of pixels over a threshold", the rule `depthscope diff` applies to final.png (seed 004's
// acceptance: the pixels that differ by >= 8/255).
#include <cstdint>
#include <vector>

#include "renderer/metrics/image.h"

namespace ds::metrics {

// Per pixel, top row first, the largest |a - b| of the four 8-bit channels (alpha too).
// Throws ds::Error for images of different sizes.
std::vector<uint8_t> largest_channel_differences(const Rgba8View& a, const Rgba8View& b);

// A pixel is over the threshold (of 255) when its largest channel difference reaches it; a
// pixel that does not differ is never over (a threshold of 0 counts every differing pixel).
constexpr bool over_threshold(uint8_t largest_difference, int threshold) {
    return largest_difference > 0 && int(largest_difference) >= threshold;
}

struct OverThreshold {
    uint64_t over = 0;    // pixels over the threshold
    uint64_t pixels = 0;  // of the image
    double percent() const { return pixels ? 100.0 * double(over) / double(pixels) : 0; }
};

// The pixels over the threshold (over_threshold). Throws ds::Error for images of different
// sizes.
OverThreshold pixels_over_threshold(const Rgba8View& a, const Rgba8View& b, int threshold);

}  // namespace ds::metrics
