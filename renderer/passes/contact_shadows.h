#pragma once
// Screen-space contact shadows (shaders/contact_shadows.comp): an 8-step ray march from each
// pixel towards the sun against the prepass depth, with a thickness test. Writes
// FrameResources::contact_shadows, R8_UNORM at full resolution, 1 = lit, 0 = occluded.
#include <cstdint>

#include "renderer/graph/graph.h"
#include "renderer/passes/compute_kernel.h"
#include "renderer/passes/frame.h"
#include "renderer/passes/frame_pass.h"
#include "renderer/settings/knob.h"

namespace ds::passes {

class ContactShadowsPass final : public FramePass {
  public:
    struct Params {
        float ray_length = 0.4f;  // world-space length of the march (m)
        float thickness = 0.2f;   // assumed thickness of what the depth buffer shows (m)
        float bias = 0.003f;      // fraction of the view distance: normal offset, depth slack
    };

    static constexpr const char* kShader = "contact_shadows.comp";
    static constexpr VkFormat kFormat = VK_FORMAT_R8_UNORM;
    static constexpr uint32_t kSteps = 8;

    // Builds the pipeline. steps: more than the default makes a reference (the tests hold the
    // default to a tolerance against one).
    explicit ContactShadowsPass(const PassServices& services, uint32_t steps = kSteps);
    const char* name() const override { return "contact_shadows"; }
    void rebuild_pipelines(
        vk::DestroyList& retired) override;  // fail-safe (ComputeKernel::rebuild)
    static constexpr Knob<bool> kKnob{"contact_shadows"};
    static std::vector<SettingDef> knobs();
    void configure(const FrameSetup& setup, FrameOptions& options) override;

    // Declares "contact_shadows" when in.options.contact_shadows: reads depth, normals
    // (sampled) and the frame uniforms (sun_direction); creates and writes
    // resources.contact_shadows.
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& resources) override;

    Params& params() { return params_; }

  private:
    ComputeKernel kernel_;
    uint32_t steps_;
    Params params_;
};

}  // namespace ds::passes
