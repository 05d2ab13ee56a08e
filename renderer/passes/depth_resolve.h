#pragma once
// depth_resolve: a multisampled depth resolved to the nearest sample (reverse-Z: MAX, else
// MIN). Natively, the pass that renders the depth (depth_prepass; forward with prepass=off)
// does it with a resolve attachment where the device offers the mode; otherwise this pass
// does it after that one, in a fullscreen draw writing gl_FragDepth from the sampled samples
// (shaders/depth_resolve.frag). The graph plans both layout changes of the MSAA depth.
#include <cstdint>

#include <vulkan/vulkan.h>

#include "renderer/passes/frame.h"
#include "renderer/passes/frame_pass.h"
#include "renderer/passes/pass_util.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/destroy_list.h"
#include "renderer/vk/image.h"
#include "renderer/vk/pipeline.h"

namespace ds::vk {
struct DeviceReport;
}

namespace ds::passes {

class DepthResolvePass final : public FramePass {
  public:
    // Which pass leaves the multisampled depth: the prepass, or forward with prepass=off.
    enum class After : uint8_t { Prepass, Forward };

    DepthResolvePass(const PassServices& services, After after);

    // Adds "depth_resolve" at msaa > 1 when the device has no native nearest-sample resolve
    // (else the writing pass resolves with a resolve attachment) and `after` wrote the depth:
    // reads res.msaa_depth (sampled), writes res.depth.
    const char* name() const override { return "depth_resolve"; }
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) override;
    void rebuild_pipelines(vk::DestroyList& retired) override { pipelines_.rebuild(retired); }

  private:
    // The single-sample depth it writes: the frame's depth_format.
    using Variant = NoVariant;

    ShaderStages compile(const Variant& variant) const;
    vk::Pipeline create(const Variant& variant, const ShaderStages& stages,
                        const graph::RenderTarget& target) const;
    void record(graph::PassContext& ctx, const FrameInputs& in, graph::ImageHandle msaa_depth);

    PassServices services_;
    After after_;
    vk::Sampler nearest_;
    vk::DescriptorSetLayout set_layout_;
    vk::PipelineLayout layout_;
    FrameDescriptorPool sets_;
    PipelineVariants<Variant> pipelines_;
};

}  // namespace ds::passes
