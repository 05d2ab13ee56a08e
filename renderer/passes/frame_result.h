#pragma once
// What a frame gives back (FrameResult and its parts) and what a caller may ask of it
// (ReadBack, InspectRequest). Plain data, below the passes: each pass fills its own part
// after the frame's fence (FramePass::collect), the facade returns it.
#include <array>
#include <compare>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/common/surface_name.h"
#include "renderer/graph/tiler.h"
#include "renderer/graph/types.h"
#include "renderer/view/image.h"

namespace ds {

// A graphics pipeline a pass drew with this frame: its debug name, whether the depth test can
// run before its fragment shader ("guaranteed" or "lost: <reasons>", shader::early_z_verdict,
// decided once per pipeline variant from its fragment SPIR-V and state) and its draws.
struct PipelineReport {
    std::string name;
    std::string early_z;
    uint32_t draws = 0;
    bool fragment_stage = true;  // false: depth only (shadow opaque, the Z-only prepass's)
};

// One pass of a frame, as measured by the GPU.
struct PassResult {
    std::string name;
    // What the pass is for: the frame's own work, a clear, or a read-back to the host
    // (graph::PassRole); reports and the Passes panel group by it.
    graph::PassRole role = graph::PassRole::Frame;
    // render_path=subpass: the render pass (graph subpass group) the pass is a subpass of, and
    // which subpass; empty for a pass on its own.
    std::string subpass_group;
    uint32_t subpass = 0;
    double gpu_ms = 0;  // from two timestamps around the pass
    // When the pass began, after the frame's first timestamp (the first pass starts at 0): the
    // same ticks as gpu_ms, so [gpu_start_ms, gpu_start_ms + gpu_ms] is the pass on the GPU's
    // clock (--trace). Both 0 when the device has no timestamps.
    double gpu_start_ms = 0;
    // Pipeline statistics (0 without the device feature). Lavapipe counts fragment shader
    // invocations per rasterized 4x4 block before the depth test: not what a prepass saves.
    uint64_t vertex_shader_invocations = 0;
    uint64_t fragment_shader_invocations = 0;
    uint64_t clipping_primitives = 0;
    // count_fragments=on (shadow, depth_prepass, forward, decals, transparent): fragments that ran
    // the fragment shader, counted on entry, summed from a per-pixel u32 image. With early fragment
    // tests (every pipeline without discard) they passed the depth test; a pipeline with discard
    // runs before its late depth test, so it counts what it rasterized.
    std::optional<uint64_t> shaded_fragments;
    // count_fragments=on, the same passes: fragments their alpha test discarded (counted
    // just before the discard; shaded_fragments includes them).
    std::optional<uint64_t> discarded_fragments;
    // count_fragments=on, the same passes and shadow: fragments their draws rasterized, what
    // reached (or, with discard, would have reached) the depth test: depth complexity.
    // Counted by a measurement draw of the same selection with the depth test off.
    std::optional<uint64_t> rasterized_fragments;
    // count_fragments=on where the device has quad subgroup operations in fragment shaders:
    // 2x2 quads that ran the fragment shader with at least one live lane (4 lanes each, the
    // rest helpers); 4 * quads / shaded_fragments is the quad overdraw.
    std::optional<uint64_t> quads;
    // The graph resources the pass declared, by name, in declaration order.
    std::vector<std::string> reads, writes;
    // Geometry passes: the pipelines it bound, in first-bind order (empty for the others).
    std::vector<PipelineReport> pipelines;
    // count_draws=on, every pass that binds the count set: its shaded fragments per scene
    // draw group (GpuScene::draw_groups order); in_view: drawn from the camera (not the
    // light), so shaded minus visible pixels is waste (DrawReport::wasted_fragments).
    std::vector<uint64_t> draw_shaded;
    bool draw_shaded_in_view = true;
    // count_draws=on, the pass that decides visibility (the prepass, else forward): per draw
    // group, the samples that passed its depth test (precise occlusion queries, summed over
    // the group's draws); none for a group the pass does not draw.
    std::vector<std::optional<uint64_t>> draw_samples_passed;
};

// One resource of the frame's graph (the inspector's Resources panel).
struct ResourceSummary {
    std::string name;
    bool is_image = true;
    VkFormat format = VK_FORMAT_UNDEFINED;  // images
    uint32_t width = 0, height = 0, samples = 1;
    graph::Semantic semantic = graph::Semantic::Other;
    // Scalar images: how they are shown. Not filled yet (Renderer's summarize copies the
    // semantic only); the read images carry it (InspectedImage::display).
    graph::Display display{};
    graph::Lifetime lifetime = graph::Lifetime::Transient;
    uint64_t bytes = 0;  // buffers
};

// msaa: how the frame was multisampled.
struct MsaaResult {
    uint32_t samples = 1;
    std::string depth_resolve;  // msaa > 1: "native-max" | "native-min" | "shader"; else ""
    // msaa > 1 and read back: pixels whose HDR colour samples are not all equal (after
    // transparent, before the resolve); exact, counted by a compute pass over every sample.
    std::optional<uint64_t> edge_pixels;
    // ReadBack::WithMsaaDepth, msaa > 1 and a D32 depth only: every depth sample (per pixel,
    // `samples` consecutive, row 0 = top) and the resolved depth (one per pixel).
    std::vector<float> depth_samples;
    std::vector<float> resolved_depth;
};

// The scene depth as the frame used it: the format depth_format gave on this device, the
// effective planes (the scene camera's, or the znear / zfar knobs) and the convention.
struct DepthResult {
    VkFormat format = VK_FORMAT_UNDEFINED;
    float znear = 0.0f, zfar = 0.0f;
    bool reverse_z = true;
};

// count_discards=on: fragments that ran the depth prepass's alpha-tested pipeline (the MASK one;
// masked_split=off: the one for all geometry), and how many of them it discarded. Exact
// (shader atomics; helper invocations do not count).
struct DiscardCounts {
    uint64_t invoked = 0;
    uint64_t discarded = 0;
};

// What a surface_id value names in the current scene (Renderer::describe_surface).
struct SurfaceInfo {
    SurfaceName name;
    uint32_t instance = 0;  // scene instance index
    uint32_t triangle = 0;  // of its mesh
};

// zfight=on: two instances whose surfaces fight, how many pixels they fight in and the
// smallest gap seen, in representable depth steps.
struct ZfightPair {
    SurfaceName a, b;  // a: the one with the lower instance index (a == b: within one mesh)
    uint64_t pixels = 0;
    uint32_t min_steps = 0;
};
// One pair fighting in one pixel (the least gap seen there).
struct ZfightHit {
    uint32_t pixel = 0;  // y * width + x
    uint32_t pair = 0;   // index into ZfightResult::pairs
    uint32_t steps = 0;
    float gap = 0;  // the same gap in scene units, along the pixel's view ray
};
struct ZfightResult {
    uint32_t steps = 0;             // zfight_steps
    uint64_t pixels = 0;            // pixels with at least one competitor
    std::vector<ZfightPair> pairs;  // most pixels first
    std::vector<ZfightHit> hits;    // by pixel, then pair: what the viewer highlights and reads
    uint64_t dropped = 0;           // competitor records past the buffer (pairs undercount)
};

// equal_check=on: pixels the prepass covered that forward did not shade (holes) and pixels
// forward shaded more than once (multiple), and the instances most involved.
struct EqualCheckSurface {
    SurfaceName name;
    uint64_t holes = 0, multiple = 0;  // pixels it won in the prepass
};
struct EqualCheckResult {
    uint64_t holes = 0, multiple = 0;
    std::vector<EqualCheckSurface> surfaces;  // most pixels first, at most ten
};

// hiz=on with count_draws=on: what the Hi-Z test says of a draw group's instances, from their
// world bounds' screen rectangle and nearest depth against the pyramid. Visible: it may be seen
// (or the box crosses the near plane, where the test says nothing); Occluded: every sample it
// could cover is farther than the pyramid's farthest depth there; Outside: off screen or
// beyond the far plane (frustum culled). A group is Visible when any instance is, else
// Occluded when any instance is, else Outside.
enum class HizVerdict : uint8_t { Visible, Occluded, Outside };
inline const char* hiz_verdict_name(HizVerdict verdict) {
    return verdict == HizVerdict::Occluded  ? "occluded"
           : verdict == HizVerdict::Outside ? "outside"
                                            : "visible";
}

// hiz_test's finding for one scene instance: the level it read, its box's nearest depth and
// the pyramid's farthest there (both 0 where the test said nothing: behind the eye, in front
// of the near plane, outside).
struct HizInstance {
    HizVerdict verdict = HizVerdict::Visible;
    uint32_t level = 0;
    float nearest = 0.0f, farthest = 0.0f;
};

// hiz=on (with the prepass): the pyramid's levels, level 0 first (images hiz.0 ... hiz.N);
// with count_draws=on also the per-group verdicts and, filled by readback_draws, the unsafe
// disagreements: groups Hi-Z calls not visible (occluded or outside) whose samples_passed > 0.
struct HizResult {
    std::vector<std::pair<uint32_t, uint32_t>> levels;  // width, height
    std::string source;                                 // "depth" | "msaa_depth"
    uint32_t samples = 1;                               // of the source (farthest of them)
    bool reverse_z = true;                              // farthest: min; else max
    std::vector<HizVerdict> groups;                     // count_draws: per draw group
    std::vector<uint32_t> occluded_instances;           // count_draws: per draw group
    std::vector<HizInstance> instances;                 // count_draws: per scene instance
    std::optional<uint64_t> unsafe;                     // count_draws: see above
    // count_draws: groups Hi-Z calls not visible that won pixels in the final depth
    // (visible_pixels > 0): wrong whatever the draw order (samples_passed counts what passed
    // when drawn, so a layer drawn before its occluder passes samples and is still hidden).
    std::optional<uint64_t> unsafe_visible;
};

// count_draws=on: one scene draw group (mesh + instance range, what forward draws in one
// call; the sorted prepass draws its instances one by one) and what each pass did with it.
struct DrawReport {
    uint32_t group = 0;  // index in the scene's draw groups
    SurfaceName name;    // mesh, material, and the node of its first instance
    uint32_t first_instance = 0, instances = 0;
    std::string alpha_mode;  // "opaque" | "mask" | "blend"
    bool decal = false;      // a coplanar overlay (drawn by the decals pass when it runs)
    // Pixels whose surface_id (the prepass's winner) is one of its instances' triangles: they
    // sum to covered_pixels (msaa > 1: sample 0's winner). None without the prepass, and for
    // a group the prepass does not draw (BLEND, decals).
    std::optional<uint64_t> visible_pixels;
    // Samples that passed the visibility pass's depth test; none where it does not draw it.
    std::optional<uint64_t> samples_passed;
    // Per counting pass (by pass name): fragments that ran its fragment shader.
    std::vector<std::pair<std::string, uint64_t>> shaded_fragments;
    // Per in-view counting pass that shaded it (> 0), where visible_pixels is known: shaded
    // minus visible, the fragments that ran its shader and do not show.
    std::vector<std::pair<std::string, int64_t>> wasted_fragments;
    // Drawn by the visibility pass and nothing of it visible (visible_pixels, or without the
    // prepass samples_passed, is 0).
    bool occluded = false;
    // hiz=on: the Hi-Z test's verdict, how many of its instances it found occluded, and
    // whether it disagrees unsafely with samples_passed (not visible, yet samples passed).
    std::optional<HizVerdict> hiz;
    uint32_t hiz_occluded_instances = 0;
    bool hiz_unsafe = false;
};

// pixel history (PixelQuery): one fragment that covered the pixel, as its pass's instrumented
// replay recorded it and the host's simulation of the pass's depth test and blending judged it
// (renderer/passes/pixel_history.h). Names come from the scene (Scene::instance_name).
struct PixelAlphaTest {
    float alpha = 0, cutoff = 0;
    bool passed = true;  // false: discarded
};
struct PixelFragment {
    std::string pass;      // the geometry pass ("depth_prepass", "forward", ...)
    std::string pipeline;  // the real pipeline that drew it (PipelineReport::name)
    uint32_t draw = 0;     // index of its draw in the pass's submission order
    uint32_t instance = 0, primitive = 0, sample = 0;
    float depth = 0;  // gl_FragCoord.z, as the depth format stores it
    bool depth_passed = false;
    float against = 0;  // the depth buffer's value when the fragment was tested
    std::optional<PixelAlphaTest> alpha_test;  // pipelines with an alpha test only
    bool shaded = false;  // the fragment shader ran in the real frame (early-Z: only if passed)
    std::optional<std::array<float, 4>> color;    // the shader's HDR output (not the prepass)
    std::optional<std::array<float, 4>> blended;  // blended passes: the colour after blending
};
struct PixelHistory {
    uint32_t x = 0, y = 0;
    std::vector<PixelFragment> fragments = {};  // submission order: pass, draw, instance, primitive
    uint64_t dropped = 0;  // records past a replay's buffer (then fragments are incomplete)
};

// The MSAA sample view (issue 15): every sample of a rectangle of the frame, as the frame left
// it (after transparent, before any resolve): the winning surface (the prepass's per-sample
// surface_id; 0 none), the depth and the HDR colour. At msaa=1 the one sample is the pixel.
struct SampleQuery {
    uint32_t x = 0, y = 0, width = 1, height = 1;  // pixels, row 0 = top
};
struct PixelSample {
    uint32_t surface = 0;  // Renderer::describe_surface; 0 nothing (or surface_ids is false)
    float depth = 0;       // as the depth format stores it (reverse-Z unless off)
    std::array<float, 4> color{};
};
struct MsaaSamples {
    SampleQuery rect;  // as read: clamped to the frame
    uint32_t samples = 1;
    bool surface_ids = false;  // false: no prepass this frame, so no surface per sample
    // Per pixel of `rect`, row by row, `samples` consecutive.
    std::vector<PixelSample> values;
    bool contains(uint32_t x, uint32_t y) const {
        return x >= rect.x && y >= rect.y && x - rect.x < rect.width && y - rect.y < rect.height;
    }
    // The samples of frame pixel (x, y); empty outside `rect`.
    std::span<const PixelSample> pixel(uint32_t x, uint32_t y) const {
        if (!contains(x, y) || values.empty()) return {};
        const size_t i = (size_t(y - rect.y) * rect.width + (x - rect.x)) * samples;
        return std::span(values).subspan(i, samples);
    }
};

struct FrameResult {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba8;      // final image, sRGB-encoded, tightly packed, top row first;
                                     // empty when the frame was rendered without read-back
    std::vector<PassResult> passes;  // in execution order
    double gpu_ms = 0;               // first pass start to last pass end, from timestamps
    double cpu_ms = 0;               // host time to record and submit the frame (not the wait)
    // Pixels some surface covers: depth differs from "far" after the prepass (or forward).
    // Read back with the image, or with count_fragments=on; none for ReadBack::No otherwise.
    std::optional<uint64_t> covered_pixels;
    std::vector<std::string> skipped;  // "gtao: skipped (prepass off)", in pass order
    // render_path=subpass: the render pass's tile budget and seed 002's merge verdict; none
    // on the dynamic path (no subpass group).
    std::optional<graph::TilerReport> tiler;
    MsaaResult msaa;
    std::optional<DepthResult> depth;              // every rendered frame has it
    std::optional<DiscardCounts> masked_discards;  // count_discards=on with the prepass
    std::optional<ZfightResult> zfight;            // zfight=on with the prepass
    std::optional<EqualCheckResult> equal_check;   // equal_check=on (prepass, EQUAL, 1x)
    std::optional<HizResult> hiz;                  // hiz=on with the prepass
    // count_draws=on: every scene draw group, in scene order; the pass whose occlusion
    // queries gave samples_passed; why visible pixels are missing ("" when they are not);
    // per pixel (row 0 = top), the draw group whose surface won + 1 (0: none; empty without
    // the prepass): what the viewer highlights for a selected draw.
    std::vector<DrawReport> draws;
    std::string draws_samples_pass;
    std::string draws_visible_note;
    std::vector<uint32_t> draw_pixels;
    // Every resource of the frame's graph, in creation order (the inspect pass's own target
    // left out).
    std::vector<ResourceSummary> resources;
    // InspectRequest: the image as read; none when the frame has no image of that name (its
    // pass is off) or nothing was asked. A list of requests: the first one's.
    std::optional<InspectedImage> inspected;
    // A list of requests: the images of the others that the frame has, in the list's order
    // (names it lacks are left out, so find them by name): what the viewer stacks over the
    // first and derives views from.
    std::vector<InspectedImage> overlays;
    // PixelQuery: every fragment that covered the pixel; none when nothing was asked.
    std::optional<PixelHistory> pixel_history;
    // SampleQuery: the rectangle's samples; none when nothing was asked.
    std::optional<MsaaSamples> msaa_samples;
};

// Read back one graph image by name at the end of the frame ("final": the tonemapped image;
// any other: a compute pass "inspect" samples it, so it appears last in FrameResult::passes).
// Renderer::render takes one or a list (one dispatch each; "final" only as the first).
struct InspectRequest {
    std::string resource;  // "" = none
    uint32_t sample = 0;   // multisampled images
};

// Pixel history for one pixel of the frame (x, y in pixels, row 0 = top): each geometry pass
// replays its draws with instrumented shaders first (graph role history).
struct PixelQuery {
    uint32_t x = 0, y = 0;
};

// Benchmarks skip the copy to host memory; WithMsaaDepth is Yes plus MsaaResult's depth.
// Color reads back the final image only (no covered pixels, no MSAA probe: the inspector).
enum class ReadBack { Yes, No, WithMsaaDepth, Color };
// Frames read back in full: the image, covered pixels and (msaa > 1) the sample probe.
inline bool reads_back_fully(ReadBack r) {
    return r == ReadBack::Yes || r == ReadBack::WithMsaaDepth;
}

}  // namespace ds
