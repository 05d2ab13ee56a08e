#pragma once
// One graph pass of a frame as measured (PassResult) and the pipelines it drew with.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "renderer/graph/types.h"

namespace ds {

// A graphics pipeline a pass drew with this frame: its debug name, whether the depth test can
// run before its fragment shader ("guaranteed" or "lost: <reasons>", spirv::early_z_verdict,
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

}  // namespace ds
