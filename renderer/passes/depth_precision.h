#pragma once
// depth_precision (depth_precision=on, or zfight=on): a compute pass after the prepass
// (shaders/depth_precision.comp). Image `depth_precision` (RGBA32F, semantic DepthStep): r,
// the distance along the view ray from the stored depth to the next representable depth
// value of the frame's format, planes and direction, in scene units; g, the distance along
// the ray; 0 where nothing was drawn. The viewer shows r on a log scale.
#include "renderer/passes/compute_kernel.h"
#include "renderer/passes/frame_pass.h"
#include "renderer/settings/knob.h"

namespace ds::passes {

class DepthPrecisionPass final : public FramePass {
  public:
    static constexpr VkFormat kFormat = VK_FORMAT_R32G32B32A32_SFLOAT;

    explicit DepthPrecisionPass(const PassServices& services);

    const char* name() const override { return "depth_precision"; }
    static constexpr Knob<bool> kKnob{"depth_precision"};
    static std::vector<SettingDef> knobs();
    void configure(const FrameSetup& setup, FrameOptions& options) override;
    // On when asked for (its knob, zfight), with the prepass, on the dynamic path.
    void resolve(FrameOptions& options) override;
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) override;
    void rebuild_pipelines(vk::DestroyList& retired) override;

  private:
    ComputeKernel kernel_;
    bool built_ = false;
};

}  // namespace ds::passes
