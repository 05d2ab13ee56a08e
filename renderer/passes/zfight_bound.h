#pragma once
// The zfight pass's depth bound (part of the zfight pass, not a frame pass of its own): a
// fullscreen graph pass "zfight_bound" that writes the stored depth moved zfight_steps + 1
// representable steps towards far into a transient depth image of the frame's format
// (shaders/zfight_bound.frag). zfight then tests closer-or-equal against it, read-only, with
// early fragment tests: the layers more than zfight_steps behind each pixel's winner are
// rejected before its shader runs, as the prepass rejects them, instead of all being shaded.
// At msaa > 1 the bound is multisampled, each sample from its own stored sample
// (res.msaa_depth), so zfight can test every sample against its own bound.
#include <cstddef>

#include <vulkan/vulkan.h>

#include "renderer/graph/graph.h"
#include "renderer/passes/frame.h"
#include "renderer/passes/pass_util.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/image.h"
#include "renderer/vk/pipeline.h"

namespace ds::passes {

// The zfight pipelines' key (the bound's and the detector's): the msaa sample count (above 1:
// the PER_SAMPLE shaders); the depth format is the target's.
struct ZfightVariant {
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    bool per_sample() const { return samples != VK_SAMPLE_COUNT_1_BIT; }
    bool operator==(const ZfightVariant&) const = default;
    size_t hash() const { return size_t(samples); }
};

class ZfightBound {
  public:
    explicit ZfightBound(const PassServices& services);

    // Adds the graph pass for a bound `steps` behind the stored depth (at msaa > 1 every
    // sample's); returns the bound image (multisampled at msaa > 1).
    graph::ImageHandle add(graph::RenderGraph& graph, const FrameInputs& in,
                           const FrameResources& res, uint32_t steps);
    void rebuild_pipelines(vk::DestroyList& retired) { pipelines_.rebuild(retired); }

  private:
    using Variant = ZfightVariant;
    void record(graph::PassContext& ctx, const FrameInputs& in, uint32_t steps,
                graph::ImageHandle stored);

    PassServices services_;
    vk::Sampler nearest_;
    vk::DescriptorSetLayout set_layout_;
    vk::PipelineLayout layout_;
    FrameDescriptorPool sets_;
    PipelineVariants<Variant> pipelines_;
};

}  // namespace ds::passes
