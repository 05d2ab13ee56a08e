#pragma once
// Upsampling and temporal accumulation of the filtered AO (shaders/ao_temporal.comp):
// ao_filtered (packed, at gtao's resolution) + the graph history "ao_history" ->
// FrameResources::ao (R8_UNORM at full resolution, what forward reads) and the next history
// (R16G16_SFLOAT: AO, view distance). Upsamples with bilinear weights times tangent-plane and
// normal agreement (no AO across depth edges or corners); reprojects with
// previous_view_projection, drops history taps of another surface (distance mismatch), blends
// the rest with history_weight. When the graph reports the history invalid (first frame,
// resize, camera cut) the output is the current value.
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
    static constexpr VkFormat kHistoryFormat = VK_FORMAT_R16G16_SFLOAT;

    explicit AoTemporalPass(const PassServices& services);  // builds the pipeline
    const char* name() const override { return "ao_temporal"; }
    void rebuild_pipelines(
        vk::DestroyList& retired) override;  // fail-safe (ComputeKernel::rebuild)
    std::optional<std::string> skipped(const FrameInputs& in) const override;

    // Declares "ao_temporal" when resources.ao_filtered is valid: reads depth, normals,
    // ao_filtered and the previous history (sampled), the frame uniforms; writes resources.ao
    // and the current history. The graph swaps the history pair after the frame.
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

    ComputeKernel kernel_;
    Params params_;
    bool last_history_valid_ = false;
};

}  // namespace ds::passes
