#include "renderer/metrics/image.h"

#include "renderer/common/error.h"

namespace ds::metrics {
namespace {

void require_sizes(const char* what, uint32_t aw, uint32_t ah, uint32_t bw, uint32_t bh) {
    if (aw != bw || ah != bh)
        throw Error(std::string(what) + ": images of different sizes (" + size_text(aw, ah) +
                    " and " + size_text(bw, bh) + ")");
}

void require_values(const char* what, uint32_t w, uint32_t h, size_t values, size_t per_pixel) {
    if (values != size_t(w) * h * per_pixel)
        throw Error(std::string(what) + ": " + size_text(w, h) + " image holds " +
                    std::to_string(values) + " values");
}

}  // namespace

std::string size_text(uint32_t width, uint32_t height) {
    return std::to_string(width) + "x" + std::to_string(height);
}

void require_same_size(const char* what, const Rgba8View& a, const Rgba8View& b) {
    require_sizes(what, a.width, a.height, b.width, b.height);
    require_values(what, a.width, a.height, a.rgba.size(), 4);
    require_values(what, b.width, b.height, b.rgba.size(), 4);
}

void require_same_size(const char* what, const LumaImage& a, const LumaImage& b) {
    require_sizes(what, a.width, a.height, b.width, b.height);
    require_values(what, a.width, a.height, a.values.size(), 1);
    require_values(what, b.width, b.height, b.values.size(), 1);
}

}  // namespace ds::metrics
