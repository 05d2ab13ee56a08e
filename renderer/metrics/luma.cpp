#include "renderer/metrics/luma.h"

#include <cmath>
#include <limits>

#include "renderer/common/error.h"

namespace ds::metrics {

LumaImage luma(const Rgba8View& image) {
    if (image.rgba.size() != image.pixels() * 4)
        throw Error("luma: " + size_text(image.width, image.height) + " image holds " +
                    std::to_string(image.rgba.size()) + " bytes");
    LumaImage out{image.width, image.height, std::vector<double>(image.pixels())};
    for (size_t p = 0; p < out.values.size(); ++p) {
        const uint8_t* c = &image.rgba[p * 4];
        out.values[p] = 0.2126 * double(c[0]) + 0.7152 * double(c[1]) + 0.0722 * double(c[2]);
    }
    return out;
}

LumaImage abs_difference(const LumaImage& a, const LumaImage& b) {
    require_same_size("luma error", a, b);
    LumaImage out{a.width, a.height, std::vector<double>(a.values.size())};
    for (size_t p = 0; p < out.values.size(); ++p)
        out.values[p] = std::fabs(a.values[p] - b.values[p]);
    return out;
}

MaskedError edge_error(const LumaImage& a, const LumaImage& b, const std::vector<bool>& mask) {
    require_same_size("edge error", a, b);
    if (mask.size() != a.values.size())
        throw Error("edge error: a mask of " + std::to_string(mask.size()) + " pixels for a " +
                    size_text(a.width, a.height) + " image");
    MaskedError out;
    double sum = 0;
    for (size_t p = 0; p < mask.size(); ++p) {
        if (!mask[p]) continue;
        sum += std::fabs(a.values[p] - b.values[p]);
        ++out.pixels;
    }
    out.mean = out.pixels ? sum / double(out.pixels) : std::numeric_limits<double>::quiet_NaN();
    return out;
}

}  // namespace ds::metrics
