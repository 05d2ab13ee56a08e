#pragma once
// decals (decal_pass=on and the scene has coplanar overlays): seed 004's fix. The overlays the
// importer classified (scene::DrawGroup::decal: triangles lying on another surface and inside
// it) skip shadow, prepass, forward, zfight and transparent, and are drawn here once, after
// forward: opaque overlays first, then MASK (alpha tested), then BLEND (alpha blended), each
// in authored order. Depth is tested closer-or-equal against the scene depth with writes off
// and a small bias towards the camera (4 steps plus one pixel's depth slope), so an overlay
// with its base's exact vertices passes where the base won, one with its own vertices inside
// the base's triangles passes despite rounding, and surfaces in front still hide both. Lit
// like transparent (shaders/transparent.frag with ALPHA_MODE), with the overlay's own normal
// and the base's AO and contact shadows.
//
// msaa > 1: draws into res.msaa_hdr against res.msaa_depth; transparent resolves afterwards.
// Pixel history (FrameInputs::pixel): decals_history replays the three steps first with the
// instrumented variants (pixel_history.h). The replay has no depth attachment, so its depths
// carry no bias: the simulated test compares the unbiased depth with the scene depth.
#include <cstdint>

#include <vulkan/vulkan.h>

#include "renderer/graph/graph.h"
#include "renderer/passes/frame.h"
#include "renderer/passes/frame_pass.h"
#include "renderer/passes/overlay_drawing.h"
#include "renderer/passes/pass_util.h"
#include "renderer/passes/pipeline_use.h"
#include "renderer/passes/rasterized_count.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/knob.h"
#include "renderer/vk/destroy_list.h"
#include "renderer/vk/pipeline.h"

namespace ds::passes {

class DecalsPass final : public FramePass {
  public:
    static constexpr const char* kName = "decals";

    explicit DecalsPass(const PassServices& services);

    const char* name() const override { return kName; }
    static constexpr Knob<bool> kKnob{"decal_pass"};
    static std::vector<SettingDef> knobs();
    void configure(const FrameSetup& setup, FrameOptions& options) override;
    void rebuild_pipelines(vk::DestroyList& retired) override {
        pipelines_.rebuild(retired);
        rasterized_.rebuild_pipelines(retired);
    }
    // Reads res.depth (read-only attachment), res.shadow_map, res.ao, res.contact_shadows
    // where valid; draws into res.hdr. Counts into res.decal_counts when valid.
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) override;
    // shaded_fragments from res.decal_counts.
    void collect(const FrameCollect& c, std::span<PassResult> own, FrameResult& frame) override;

  private:
    struct Variant {
        scene::AlphaMode mode = scene::AlphaMode::Opaque;
        bool counting = false;  // COUNT_FRAGMENTS=1
        bool reverse_z = true;  // the bias's direction
        bool history = false;   // PIXEL_HISTORY=1: the replay's, no attachments
        VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
        VkFormat depth = VK_FORMAT_UNDEFINED;  // the frame's depth_format
        bool count_draws = false;              // COUNT_DRAWS=1 (with counting)
        // render_path=subpass: the render pass and subpass it draws in (null: its own).
        VkRenderPass render_pass = VK_NULL_HANDLE;
        uint32_t subpass = 0;
        bool operator==(const Variant&) const = default;
        size_t hash() const {
            return hash_fields(int(mode), counting, reverse_z, history, int(samples), int(depth),
                               count_draws, render_pass, subpass);
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
    std::vector<HistoryPipeline> history_pipelines_;  // this frame's real ones, by log tag
};

}  // namespace ds::passes
