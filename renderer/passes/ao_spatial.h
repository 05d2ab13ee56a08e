#pragma once
// Edge-aware spatial filter of GTAO (shaders/ao_spatial.comp): ao_raw -> ao_filtered, both
// packed R16G16B16A16_SFLOAT (AO, view distance, octahedral view normal) at ao_raw's
// resolution. A separable 5-tap tent (two dispatches through an intermediate image) weighted
// by tangent-plane distance and normal agreement: removes gtao's 4x4 rotation pattern without
// bleeding across depth edges. ao_temporal upsamples the result to full resolution.
#include "renderer/graph/graph.h"
#include "renderer/passes/compute_kernel.h"
#include "renderer/passes/frame.h"
#include "renderer/passes/frame_pass.h"

namespace ds::passes {

class AoSpatialPass final : public FramePass {
  public:
    struct Params {
        float plane_tolerance = 0.02f;  // tangent-plane distance / view distance of weight 1/e
    };

    static constexpr const char* kShader = "ao_spatial.comp";
    static constexpr VkFormat kFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
    // The horizontal result, packed like ao_raw (and with its values over 1).
    static constexpr const char* kIntermediateName = "ao_spatial_h";
    static constexpr VkFormat kIntermediateFormat = VK_FORMAT_R16G16B16A16_SFLOAT;

    explicit AoSpatialPass(const PassServices& services);  // builds the pipelines
    // Fail-safe: both directions compile first; on any error both keep their pipelines.
    const char* name() const override { return "ao_spatial"; }
    void rebuild_pipelines(vk::DestroyList& retired) override;
    void configure(const FrameSetup& setup, FrameOptions& options) override;

    // Declares "ao_spatial" when resources.ao_raw is valid (gtao ran): reads ao_raw (sampled)
    // and the frame uniforms; creates and writes resources.ao_filtered at ao_raw's size (and
    // its intermediate, which the pass writes and then samples: GENERAL layout, with a barrier
    // between the two dispatches).
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& resources) override;

    Params& params() { return params_; }

  private:
    ComputeKernel horizontal_;
    ComputeKernel vertical_;
    Params params_;
};

}  // namespace ds::passes
