#include "ui/sample_view.h"

#include <algorithm>
#include <cmath>

#include "renderer/view/decode.h"

namespace ds::ui {

std::optional<SampleQuery> visible_sample_rect(float centre_x, float centre_y, float zoom, float w,
                                               float h, uint32_t frame_w, uint32_t frame_h) {
    if (zoom <= 0.0f || w < 1.0f || h < 1.0f || frame_w == 0 || frame_h == 0) return std::nullopt;
    const float half_w = 0.5f * w / zoom, half_h = 0.5f * h / zoom;
    const float cx = centre_x * float(frame_w), cy = centre_y * float(frame_h);
    auto snap_down = [](float v) {
        const int64_t cell = int64_t(std::floor(v / float(kSampleGrid))) - 1;  // one cell margin
        return std::max<int64_t>(cell, 0) * kSampleGrid;
    };
    auto snap_up = [](float v, uint32_t size) {
        const int64_t cell = int64_t(std::ceil(v / float(kSampleGrid))) + 1;
        return std::min<int64_t>(cell * kSampleGrid, size);
    };
    const int64_t x0 = snap_down(cx - half_w), y0 = snap_down(cy - half_h);
    const int64_t x1 = snap_up(cx + half_w, frame_w), y1 = snap_up(cy + half_h, frame_h);
    if (x1 <= x0 || y1 <= y0 || x0 >= int64_t(frame_w) || y0 >= int64_t(frame_h))
        return std::nullopt;
    return SampleQuery{uint32_t(x0), uint32_t(y0), uint32_t(x1 - x0), uint32_t(y1 - y0)};
}

view::SamplePosition sample_position(uint32_t samples, uint32_t i, bool& standard) {
    const auto table = view::standard_sample_positions(samples);
    if (i < table.size()) return table[i];
    // No table for this count: spread them on a grid (what the view labels approximate).
    standard = false;
    const uint32_t side = std::max(1u, uint32_t(std::ceil(std::sqrt(float(samples)))));
    return {(float(i % side) + 0.5f) / float(side), (float(i / side) + 0.5f) / float(side)};
}

std::optional<PixelSampleList> sample_list(const MsaaSamples& samples, uint32_t x, uint32_t y,
                                           const DepthResult& depth, bool standard_positions,
                                           const DescribeSurface& describe) {
    const std::span<const PixelSample> pixel = samples.pixel(x, y);
    if (pixel.empty()) return std::nullopt;
    PixelSampleList list{x, y, samples.samples, samples.surface_ids, standard_positions, {}, {}};
    for (uint32_t i = 0; i < pixel.size(); ++i) {
        const PixelSample& s = pixel[i];
        SampleRow row{
            .index = i,
            .position = sample_position(samples.samples, i, list.standard_positions),
            .surface = s.surface,
            .info = s.surface && describe ? describe(s.surface) : std::nullopt,
            .depth = s.depth,
            .linear_depth = view::linear_depth(s.depth, depth.reverse_z, depth.znear, depth.zfar),
            .color = s.color};
        auto it = std::find_if(list.surfaces.begin(), list.surfaces.end(),
                               [&](const SurfaceSamples& c) { return c.surface == s.surface; });
        if (it == list.surfaces.end())
            it = list.surfaces.insert(list.surfaces.end(), {s.surface, row.info, 0u});
        it->mask |= 1u << i;
        list.rows.push_back(std::move(row));
    }
    return list;
}

std::vector<CoverageRow> coverage_rows(const PixelHistory& history, const MsaaSamples& samples,
                                       const DescribeSurface& describe) {
    std::vector<CoverageRow> rows;
    const std::span<const PixelSample> pixel = samples.pixel(history.x, history.y);
    for (const PixelFragment& f : history.fragments) {
        if (f.pass != "depth_prepass" || f.sample >= 32) continue;
        auto it = std::find_if(rows.begin(), rows.end(), [&](const CoverageRow& r) {
            return r.instance == f.instance && r.primitive == f.primitive;
        });
        if (it == rows.end()) {
            CoverageRow row{f.instance, f.primitive, 0u, 0u, f.alpha_test.has_value(), {}};
            if (f.alpha_test) row.alpha = f.alpha_test->alpha;
            it = rows.insert(rows.end(), row);
        }
        it->rasterized |= 1u << f.sample;
    }
    // Kept: the samples whose winner at the end of the frame is this fragment's triangle.
    for (uint32_t i = 0; i < pixel.size() && i < 32; ++i) {
        if (!pixel[i].surface || !describe) continue;
        const std::optional<SurfaceInfo> s = describe(pixel[i].surface);
        if (!s) continue;
        for (CoverageRow& r : rows)
            if (r.instance == s->instance && r.primitive == s->triangle) r.kept |= 1u << i;
    }
    return rows;
}

std::string mask_text(uint32_t mask, uint32_t samples) {
    std::string text;
    for (uint32_t i = 0; i < samples && i < 32; ++i) text += (mask >> i) & 1u ? 'x' : '.';
    return text;
}

}  // namespace ds::ui
