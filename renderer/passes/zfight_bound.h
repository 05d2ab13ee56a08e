#pragma once
// The zfight pass's depth bound (part of the zfight pass, not a frame pass of its own): a
// fullscreen graph pass "zfight_bound" that writes the stored depth moved zfight_steps + 1
// representable steps towards far into a transient depth image of the frame's format
// (shaders/zfight_bound.frag). zfight then tests closer-or-equal against it, read-only, with
// early fragment tests: the layers more than zfight_steps behind each pixel's winner are
// rejected before its shader runs, as the prepass rejects them, instead of all being shaded.
#include <vulkan/vulkan.h>

#include "renderer/graph/graph.h"
#include "renderer/passes/frame.h"
#include "renderer/passes/pass_util.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/image.h"
#include "renderer/vk/pipeline.h"

namespace ds::passes {

class ZfightBound {
  public:
    explicit ZfightBound(const PassServices& services);

    // Adds the graph pass for a bound `steps` behind the stored depth; returns the bound image.
    graph::ImageHandle add(graph::RenderGraph& graph, const FrameInputs& in,
                           const FrameResources& res, uint32_t steps);
    void rebuild_pipelines(vk::DestroyList& retired) { pipelines_.rebuild(retired); }

  private:
    using Variant = DepthFormatVariant;
    void record(graph::PassContext& ctx, const FrameInputs& in, uint32_t steps,
                graph::ImageHandle stored, graph::ImageHandle bound);

    PassServices services_;
    vk::Sampler nearest_;
    vk::DescriptorSetLayout set_layout_;
    vk::PipelineLayout layout_;
    FrameDescriptorPool sets_;
    PipelineVariants<Variant> pipelines_;
};

}  // namespace ds::passes
