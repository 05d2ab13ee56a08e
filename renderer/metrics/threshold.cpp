#include "renderer/metrics/threshold.h"

#include <algorithm>
#include <cstdlib>

namespace ds::metrics {

std::vector<uint8_t> largest_channel_differences(const Rgba8View& a, const Rgba8View& b) {
    require_same_size("pixel difference", a, b);
    std::vector<uint8_t> out(a.pixels());
    for (size_t p = 0; p < out.size(); ++p) {
        int largest = 0;
        for (size_t c = 0; c < 4; ++c)
            largest = std::max(largest, std::abs(int(a.rgba[p * 4 + c]) - int(b.rgba[p * 4 + c])));
        out[p] = uint8_t(largest);
    }
    return out;
}

OverThreshold pixels_over_threshold(const Rgba8View& a, const Rgba8View& b, int threshold) {
    OverThreshold out;
    for (const uint8_t d : largest_channel_differences(a, b))
        out.over += over_threshold(d, threshold) ? 1 : 0;
    out.pixels = a.pixels();
    return out;
}

}  // namespace ds::metrics
