#pragma once
// tonemap: HDR -> exposure -> ACES fit -> sRGB, into the final image (R8G8B8A8_SRGB, which
// the renderer imports and reads back). A fullscreen triangle in a graphics pass: storage
// images cannot be _SRGB, a colour attachment encodes for free.
#include <cstdint>

#include <vulkan/vulkan.h>

#include "renderer/graph/graph.h"
#include "renderer/passes/frame.h"
#include "renderer/passes/frame_pass.h"
#include "renderer/passes/pass_util.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/destroy_list.h"
#include "renderer/vk/image.h"
#include "renderer/vk/pipeline.h"

namespace ds::passes {

class TonemapPass final : public FramePass {
  public:
    static constexpr const char* kName = "tonemap";
    static constexpr VkFormat kFinalFormat = passes::kFinalFormat;

    explicit TonemapPass(const PassServices& services);

    const char* name() const override { return kName; }
    void rebuild_pipelines(vk::DestroyList& retired) override;
    // Samples res.hdr, writes res.final_image (both provided).
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) override;

  private:
    ShaderStages compile(const NoVariant& variant) const;
    vk::Pipeline create(const NoVariant& variant, const ShaderStages& stages,
                        const graph::RenderTarget& target) const;

    PassServices services_;
    vk::DescriptorSetLayout hdr_layout_;
    vk::PipelineLayout layout_;
    FrameDescriptorPool sets_;
    vk::Sampler nearest_;
    PipelineVariants<NoVariant> pipelines_;
};

}  // namespace ds::passes
