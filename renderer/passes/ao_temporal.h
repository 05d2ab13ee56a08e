#pragma once
// Temporal accumulation and upsampling of the filtered AO (shaders/ao_temporal.comp), two
// dispatches: ao_filtered (packed, at gtao's resolution) + the graph history "ao_history"
// (packed alike: R16G16B16A16_SFLOAT AO, view distance, octahedral view normal, at the same
// resolution) -> the current history, reprojected with previous_view_projection, taps of
// another surface (distance mismatch) dropped, the rest blended with history_weight; then the
// current history -> FrameResources::ao (R8_UNORM at full resolution, what forward reads),
// bilinear weights times tangent-plane and normal agreement (no AO across depth edges or
// corners). When the graph reports the history invalid (first frame, resize, camera cut) the
// history is the current value.
#include "renderer/graph/graph.h"
#include "renderer/passes/compute_kernel.h"
#include "renderer/passes/frame.h"
#include "renderer/passes/frame_pass.h"

namespace ds::passes {

class AoTemporalPass final : public FramePass {
  public:
    struct Params {
        float history_weight = 0.9f;    // share of the history in the blend
        float depth_tolerance = 0.05f;  // accepted relative distance mismatch of a history tap
        // Upsampling: a pixel's distance from a texel's tangent plane (fraction of its view
        // distance) of weight 1/e; ao_spatial's plane_tolerance.
        float plane_tolerance = 0.02f;
    };

    static constexpr const char* kShader = "ao_temporal.comp";
    static constexpr const char* kHistoryName = "ao_history";
    static constexpr VkFormat kFormat = VK_FORMAT_R8_UNORM;
    static constexpr VkFormat kHistoryFormat = VK_FORMAT_R16G16B16A16_SFLOAT;

    explicit AoTemporalPass(const PassServices& services);  // builds the pipelines
    const char* name() const override { return "ao_temporal"; }
    // Fail-safe: both dispatches' kernels compile first; on any error both keep theirs.
    void rebuild_pipelines(vk::DestroyList& retired) override;
    void configure(const FrameSetup& setup, FrameOptions& options) override;

    // Declares "ao_temporal" when resources.ao_filtered is valid: reads ao_filtered and the
    // previous history (sampled), the frame uniforms, depth and normals (sampled, for the
    // upsample); writes the current history (at ao_filtered's size; written, then sampled:
    // GENERAL layout, a barrier between the dispatches) and resources.ao. The graph swaps the
    // history pair after the frame.
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& resources) override;

    Params& params() { return params_; }
    // Whether the last recorded frame blended with a history (false: output = current).
    bool last_history_valid() const { return last_history_valid_; }

  private:
    struct Push {  // std430 twin of ao_temporal.comp's Params
        uint32_t history_valid;
        float history_weight;
        float depth_tolerance;
        float plane_tolerance;
    };

    ComputeKernel accumulate_;  // at AO resolution
    ComputeKernel upsample_;    // at full resolution
    Params params_;
    bool last_history_valid_ = false;
};

}  // namespace ds::passes
