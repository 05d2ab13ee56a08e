#pragma once
// The MSAA sample view (issue 15), the model side: no ImGui, no Vulkan. Zoomed in to at least
// kSampleViewZoom screen pixels per texel, the inspector asks each scene frame for every
// sample of the texels the viewer shows (a SampleQuery of the visible rectangle, on a coarse
// grid so small pans reuse it); the viewer draws each sample at its position inside its pixel
// in its surface's colour, and hovering lists a pixel's samples (sample_list). For a picked
// pixel, coverage_rows() sets the prepass's rasterized coverage of each fragment (from the
// pixel history's per-sample records: what gl_SampleMaskIn held, before the alpha test or
// alpha to coverage) against the samples the fragment's surface holds at the end of the frame.
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "renderer/passes/frame_result.h"
#include "renderer/passes/msaa_samples.h"
#include "renderer/passes/pixel_history.h"
#include "renderer/renderer.h"
#include "renderer/view/sample_positions.h"

namespace ds::ui {

// Screen pixels per texel from which the viewer draws samples.
inline constexpr float kSampleViewZoom = 8.0f;
// The query's rectangle snaps outwards to this grid (texels), with one cell of margin.
inline constexpr uint32_t kSampleGrid = 16;

// The texels the viewer shows (centre and zoom as ViewerState has them, the viewport `w` x
// `h` framebuffer pixels) of a `frame_w` x `frame_h` frame, snapped to kSampleGrid; none when
// nothing is visible.
std::optional<SampleQuery> visible_sample_rect(float centre_x, float centre_y, float zoom, float w,
                                               float h, uint32_t frame_w, uint32_t frame_h);

// Where sample i of an n-sample pixel lies: the standard table's position (standard = true),
// else an even spread on a diagonal-free grid, which the view labels approximate.
view::SamplePosition sample_position(uint32_t samples, uint32_t i, bool& standard);

// One sample of a pixel, as the hover list shows it.
struct SampleRow {
    uint32_t index = 0;
    view::SamplePosition position;
    uint32_t surface = 0;               // 0: nothing drawn (or no surface ids)
    std::optional<SurfaceInfo> info;    // the surface, named
    float depth = 0, linear_depth = 0;  // raw as stored, and along the view axis
    std::array<float, 4> color{};
};
// A surface present in a pixel and which of its samples hold it (bit i: sample i).
struct SurfaceSamples {
    uint32_t surface = 0;
    std::optional<SurfaceInfo> info;
    uint32_t mask = 0;
};
struct PixelSampleList {
    uint32_t x = 0, y = 0, samples = 1;
    bool surface_ids = false;              // false: the frame had no prepass (surfaces unknown)
    bool standard_positions = true;        // false: positions are approximate
    std::vector<SampleRow> rows;           // by sample index
    std::vector<SurfaceSamples> surfaces;  // in order of first sample
};
// Pixel (x, y)'s samples from `samples`; none when the rectangle does not hold it.
std::optional<PixelSampleList> sample_list(const MsaaSamples& samples, uint32_t x, uint32_t y,
                                           const DepthResult& depth, bool standard_positions,
                                           const DescribeSurface& describe);

// One prepass fragment (instance, primitive) of a picked pixel at msaa > 1: the samples it was
// rasterized to (before any alpha test) and those its surface holds at the end of the frame
// (after alpha to coverage and every depth test).
struct CoverageRow {
    uint32_t instance = 0, primitive = 0;
    uint32_t rasterized = 0, kept = 0;  // sample masks
    bool alpha_tested = false;          // its pipeline has the alpha test (MASK material)
    std::optional<float> alpha;         // the alpha it tested (first sample's record)
};
std::vector<CoverageRow> coverage_rows(const PixelHistory& history, const MsaaSamples& samples,
                                       const DescribeSurface& describe);
// "x.x." for a mask over `samples` bits: sample 0 first.
std::string mask_text(uint32_t mask, uint32_t samples);

}  // namespace ds::ui
