#pragma once
// skybox: the procedural sky (gradient, sun glow and disc; shaders/common/sky.glsl) drawn
// after forward as one fullscreen triangle at the far depth, tested closer-or-equal
// (GREATER_OR_EQUAL with reverse-Z) against the scene depth with writes off: only pixels no
// surface covered pass, so the sky shades the background alone and never touches the
// prepass depth (seed 004). With sky=off this pass is left out and the background keeps
// forward's clear colour.
#include <vulkan/vulkan.h>

#include "renderer/graph/graph.h"
#include "renderer/passes/frame.h"
#include "renderer/passes/frame_pass.h"
#include "renderer/passes/pass_util.h"
#include "renderer/settings/knob.h"
#include "renderer/vk/destroy_list.h"
#include "renderer/vk/pipeline.h"

namespace ds::passes {

class SkyboxPass final : public FramePass {
  public:
    static constexpr const char* kName = "skybox";

    explicit SkyboxPass(const PassServices& services);

    const char* name() const override { return kName; }
    void rebuild_pipelines(vk::DestroyList& retired) override;
    static constexpr Knob<bool> kKnob{"sky"};
    static std::vector<SettingDef> knobs();
    void configure(const FrameSetup& setup, FrameOptions& options) override;
    // Reads res.depth (read-only attachment), draws into res.hdr. render_path=subpass: in
    // forward's subpass (same attachments).
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) override;

  private:
    // The frame's sample count (the depth format is the target's).
    struct Variant {
        VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
        bool operator==(const Variant&) const = default;
        size_t hash() const { return hash_fields(int(samples)); }
    };

    ShaderStages compile(const Variant& variant) const;
    vk::Pipeline create(const Variant& variant, const ShaderStages& stages,
                        const graph::RenderTarget& target) const;

    PassServices services_;
    vk::PipelineLayout layout_;
    PipelineVariants<Variant> pipelines_;
};

}  // namespace ds::passes
