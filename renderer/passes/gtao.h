#pragma once
// GTAO: horizon-based ground-truth ambient occlusion from the prepass depth and normals
// (shaders/gtao.comp). Writes FrameResources::ao_raw, R16G16B16A16_SFLOAT: r visibility (1 =
// unoccluded; a single texel may exceed 1: only the spatial average is bounded, see
// gtao.comp), g the view distance (0: sky), ba the octahedral view-space normal of the pixel
// the texel stands for, so that the filters' taps are one fetch each. At `resolution_scale`
// of the output (default half: a quarter of the work on lavapipe; ao_spatial filters at this
// resolution and ao_temporal upsamples edge-aware to full resolution).
#include <cstdint>

#include "renderer/graph/graph.h"
#include "renderer/passes/compute_kernel.h"
#include "renderer/passes/frame.h"
#include "renderer/passes/frame_pass.h"
#include "renderer/settings/knob.h"

namespace ds::passes {

class GtaoPass final : public FramePass {
  public:
    struct Params {
        float radius = 1.0f;           // world-space radius (m) in which occluders count
        float falloff = 0.6f;          // fraction of the radius over which occluders fade out
        float max_radius_px = 256.0f;  // projected radius cap, full-resolution pixels
        float power = 1.0f;            // visibility ^ power (1 = physically based)
    };

    static constexpr const char* kShader = "gtao.comp";
    static constexpr VkFormat kFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
    static constexpr uint32_t kSlices = 2;  // x16 rotations of the 4x4 pattern after ao_spatial
    static constexpr uint32_t kSteps = 4;   // per side of a slice

    // Builds the pipeline (throws shader::ShaderError / ds::Error). resolution_scale: 0.5
    // (half, the default) or 1 (full). slices / steps: more than the defaults make a
    // high-quality reference (the tests compare the defaults against one).
    explicit GtaoPass(const PassServices& services, float resolution_scale = 0.5f,
                      uint32_t slices = kSlices, uint32_t steps = kSteps);

    // Fail-safe: see ComputeKernel::rebuild.
    const char* name() const override { return "gtao"; }
    void rebuild_pipelines(vk::DestroyList& retired) override;
    static constexpr Knob<bool> kKnob{"gtao"};
    static std::vector<SettingDef> knobs();
    void configure(const FrameSetup& setup, FrameOptions& options) override;

    // Declares "gtao" when in.options.gtao: reads depth, normals (sampled) and the frame
    // uniforms; creates and writes resources.ao_raw. Otherwise adds nothing.
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& resources) override;

    Params& params() { return params_; }
    float resolution_scale() const { return scale_; }

  private:
    ComputeKernel kernel_;
    float scale_;
    uint32_t slices_, steps_;
    Params params_;
};

}  // namespace ds::passes
