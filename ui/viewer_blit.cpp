#include "ui/viewer_blit.h"

#include <algorithm>
#include <cmath>

namespace ds::ui {

// The part of [src] that lands inside [dst] once both are clipped to the image and the
// viewport; false when nothing is visible.
bool clip_blit(const ViewerBlit& v, TargetSize target, BlitRegion& out) {
    if (!v.rgba8 || v.width == 0 || v.height == 0 || v.src_w <= 0 || v.src_h <= 0 || v.dst_w <= 0 ||
        v.dst_h <= 0)
        return false;
    const float scale_x = v.dst_w / v.src_w, scale_y = v.dst_h / v.src_h;
    // Image rectangle, in target pixels.
    float x0 = v.dst_x - v.src_x * scale_x, y0 = v.dst_y - v.src_y * scale_y;
    float x1 = x0 + float(v.width) * scale_x, y1 = y0 + float(v.height) * scale_y;
    // Clip to the viewport and the target.
    const float cx0 = std::max({x0, v.dst_x, 0.0f}), cy0 = std::max({y0, v.dst_y, 0.0f});
    const float cx1 = std::min({x1, v.dst_x + v.dst_w, float(target.width)});
    const float cy1 = std::min({y1, v.dst_y + v.dst_h, float(target.height)});
    if (cx1 - cx0 < 1.0f || cy1 - cy0 < 1.0f) return false;
    // An integer magnification (zoom 2, 4, 8 ...) with the image's edge on a whole pixel: blit
    // only the whole texels inside the viewport, so the ratio is exact and every destination
    // pixel centre lies mid-texel. NEAREST then samples the same texel on every device (at a
    // near-integer ratio a centre can land within rounding of a texel edge, where NVIDIA and
    // lavapipe pick neighbours differently); the partial texels at the edges, narrower than
    // one texel, stay background.
    const float zx = std::round(scale_x), zy = std::round(scale_y);
    if (zx >= 1.0f && zy >= 1.0f && std::abs(scale_x - zx) < 1e-4f &&
        std::abs(scale_y - zy) < 1e-4f) {
        const float ox = std::round(x0), oy = std::round(y0);
        out.sx0 = int32_t(std::clamp(std::ceil((cx0 - ox) / zx), 0.0f, float(v.width)));
        out.sx1 = int32_t(std::clamp(std::floor((cx1 - ox) / zx), 0.0f, float(v.width)));
        out.sy0 = int32_t(std::clamp(std::ceil((cy0 - oy) / zy), 0.0f, float(v.height)));
        out.sy1 = int32_t(std::clamp(std::floor((cy1 - oy) / zy), 0.0f, float(v.height)));
        out.dx0 = int32_t(ox + float(out.sx0) * zx);
        out.dx1 = int32_t(ox + float(out.sx1) * zx);
        out.dy0 = int32_t(oy + float(out.sy0) * zy);
        out.dy1 = int32_t(oy + float(out.sy1) * zy);
        return out.sx1 > out.sx0 && out.sy1 > out.sy0;
    }
    // Whole destination pixels, and the source region they show.
    out.dx0 = int32_t(std::floor(cx0));
    out.dy0 = int32_t(std::floor(cy0));
    out.dx1 = int32_t(std::ceil(cx1));
    out.dy1 = int32_t(std::ceil(cy1));
    auto src_of = [](float d, float origin, float scale, uint32_t size) {
        return int32_t(std::clamp(std::lround((d - origin) / scale), 0L, long(size)));
    };
    out.sx0 = src_of(float(out.dx0), x0, scale_x, v.width);
    out.sx1 = src_of(float(out.dx1), x0, scale_x, v.width);
    out.sy0 = src_of(float(out.dy0), y0, scale_y, v.height);
    out.sy1 = src_of(float(out.dy1), y0, scale_y, v.height);
    return out.sx1 > out.sx0 && out.sy1 > out.sy0;
}

std::optional<std::array<uint32_t, 2>> texel_at(const ViewerBlit& viewer, TargetSize target,
                                                float x, float y) {
    BlitRegion r{};
    if (!clip_blit(viewer, target, r)) return std::nullopt;
    const int32_t px = int32_t(std::floor(x)), py = int32_t(std::floor(y));
    if (px < r.dx0 || px >= r.dx1 || py < r.dy0 || py >= r.dy1) return std::nullopt;
    // What a NEAREST blit samples for the centre of destination pixel (px, py).
    const float u =
        float(r.sx0) + (float(px - r.dx0) + 0.5f) * float(r.sx1 - r.sx0) / float(r.dx1 - r.dx0);
    const float v =
        float(r.sy0) + (float(py - r.dy0) + 0.5f) * float(r.sy1 - r.sy0) / float(r.dy1 - r.dy0);
    const uint32_t tx = std::min(uint32_t(std::max(u, 0.0f)), viewer.width - 1);
    const uint32_t ty = std::min(uint32_t(std::max(v, 0.0f)), viewer.height - 1);
    return std::array<uint32_t, 2>{tx, ty};
}

}  // namespace ds::ui
