#pragma once
// transparent: BLEND materials, after the sky, one instance at a time back to front, alpha
// blended into the HDR image. Depth is tested closer-or-equal (GREATER_OR_EQUAL with
// reverse-Z) against the scene depth with writes off: decals lying exactly on a wall or the
// floor (the atrium's, Sponza's) have that surface's depth and pass, surfaces in front hide
// them, and they never hide each other. They are drawn here only (not by shadow, prepass or
// forward), so each appears exactly once (seed 004).
//
// msaa > 1: the last pass that draws multisampled. It blends into res.msaa_hdr against
// res.msaa_depth and resolves the colour (AVERAGE) into res.hdr, which it creates, at the
// end of its rendering; forward and skybox have drawn every sample before.
// Pixel history (FrameInputs::pixel): transparent_history replays the same sorted draws first
// with the instrumented variant (pixel_history.h), reading the depth and the HDR colour there.
#include <cstdint>

#include <vulkan/vulkan.h>

#include "renderer/graph/graph.h"
#include "renderer/passes/frame.h"
#include "renderer/passes/frame_pass.h"
#include "renderer/passes/overlay_drawing.h"
#include "renderer/passes/pass_util.h"
#include "renderer/passes/pipeline_use.h"
#include "renderer/passes/rasterized_count.h"
#include "renderer/vk/destroy_list.h"
#include "renderer/vk/pipeline.h"

namespace ds::passes {

class TransparentPass final : public FramePass {
  public:
    static constexpr const char* kName = "transparent";

    explicit TransparentPass(const PassServices& services);

    const char* name() const override { return kName; }
    void rebuild_pipelines(vk::DestroyList& retired) override;
    // shaded_fragments from res.transparent_counts.
    void collect(const FrameCollect& c, std::span<PassResult> own, FrameResult& frame) override;
    // Reads res.depth (read-only attachment), res.shadow_map, res.ao, res.contact_shadows
    // where valid; blends into res.hdr. Counts into res.transparent_counts when valid.
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) override;

  private:
    struct Variant {
        bool counting = false;  // COUNT_FRAGMENTS=1
        bool history = false;   // PIXEL_HISTORY=1: the replay's, no attachments
        VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
        VkFormat depth = VK_FORMAT_UNDEFINED;  // the frame's depth_format
        bool count_draws = false;              // COUNT_DRAWS=1 (with counting)
        // render_path=subpass: the render pass and subpass it draws in (null: its own).
        VkRenderPass render_pass = VK_NULL_HANDLE;
        uint32_t subpass = 0;
        bool operator==(const Variant&) const = default;
        size_t hash() const {
            return hash_fields(counting, history, int(samples), int(depth), count_draws,
                               render_pass, subpass);
        }
    };

    ShaderStages compile(const Variant& variant) const;
    vk::Pipeline create(const Variant& variant, const ShaderStages& stages) const;
    static std::string pipeline_name(const Variant& variant);

    PassServices services_;
    OverlayDrawing drawing_;
    RasterizedCount rasterized_;
    PipelineVariants<Variant> pipelines_;
    PipelineUses uses_;  // this frame's
    PixelHistoryReplay history_;
    std::vector<HistoryPipeline> history_pipelines_;  // this frame's real one
};

}  // namespace ds::passes
