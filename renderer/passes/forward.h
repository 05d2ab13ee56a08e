#pragma once
// forward: metallic-roughness PBR (GGX, Smith, Schlick) lit by the sun with PCF shadows and
// contact shadows, and a hemispherical ambient with material AO x GTAO, into the HDR image
// (R16G16B16A16_SFLOAT, cleared to the background colour; tonemap is its own pass).
//
// With the prepass: depth is loaded and never stored (STORE_OP_NONE, read-only layout), the
// test is EQUAL (or the closer-or-equal one with depth_compare=greater_or_equal), writes off,
// and normal and roughness come from the prepass images (prepass_mode=gbuffer) or, with the
// Z-only prepass (prepass_mode=depth), from the material as without a prepass. With EQUAL no
// forward pipeline has a discard: EQUAL already keeps only what the masked prepass kept, so every
// one keeps early-Z. greater_or_equal would let the cut-out parts of MASK surfaces through (they
// are nearer than what the prepass kept), so there MASK keeps its alpha test, in its own pipeline.
// Without the prepass (prepass=off): depth is cleared and written with the closer test,
// opaque first, then MASK with a discard in its own pipeline. invariant=off swaps in a
// vertex shader without `invariant` and with a different (equal in exact arithmetic)
// expression.
// msaa > 1 only: sample_shading=on runs every pipeline once per sample (minSampleShading 1);
// alpha_to_coverage=on makes the MASK pipelines (those with the alpha test) write a sharpened
// alpha and let alpha-to-coverage cut the samples instead of discarding whole pixels.
// BLEND materials are the transparent pass's.
//
// msaa > 1: draws into res.msaa_hdr (cleared and stored: skybox and transparent add to it,
// and transparent resolves it into res.hdr) against res.msaa_depth. Without the prepass it
// writes that depth and resolves it to the nearest sample into res.depth, natively, or the
// depth_resolve pass that follows does.
// Pixel history (FrameInputs::pixel): forward_history replays draw_scene() first with the
// instrumented variants (pixel_history.h), reading the depth the prepass left (or from the
// cleared depth without it).
#include <array>
#include <cstdint>

#include <vulkan/vulkan.h>

#include "renderer/graph/graph.h"
#include "renderer/passes/frame.h"
#include "renderer/passes/frame_pass.h"
#include "renderer/passes/geometry_instrument.h"
#include "renderer/passes/lighting_set.h"
#include "renderer/passes/pass_util.h"
#include "renderer/settings/knob.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/destroy_list.h"
#include "renderer/vk/pipeline.h"

namespace ds::passes {

class ForwardPass final : public FramePass {
  public:
    static constexpr const char* kName = "forward";
    static constexpr VkFormat kHdrFormat = passes::kHdrFormat;

    explicit ForwardPass(const PassServices& services);

    const char* name() const override { return kName; }
    static constexpr Knob<bool> kInvariant{"invariant"};
    static std::vector<SettingDef> knobs();
    void configure(const FrameSetup& setup, FrameOptions& options) override;
    void rebuild_pipelines(vk::DestroyList& retired) override;
    // Creates res.hdr (msaa > 1: draws into res.msaa_hdr instead). Reads res.depth (writes it
    // without the prepass), res.shadow_map, res.normals, res.roughness, res.ao, res.contact_shadows
    // where valid. Counts into res.forward_counts when it is valid.
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) override;
    // shaded_fragments from res.forward_counts.
    void collect(const FrameCollect& c, std::span<PassResult> own, FrameResult& frame) override;

  private:
    struct Variant {
        bool prepass_inputs = false;     // PREPASS=1: reads the prepass normals (no discard)
        bool alpha_mask = false;         // ALPHA_MASK=1 (not with prepass + EQUAL)
        bool non_invariant = false;      // invariant=off vertex shader
        bool counting = false;           // COUNT_FRAGMENTS=1
        bool sample_shading = false;     // sample_shading=on (msaa > 1)
        bool alpha_to_coverage = false;  // MASK pipelines, alpha_to_coverage=on
        bool history = false;            // PIXEL_HISTORY=1: the replay's, no attachments
        VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
        bool count_draws = false;  // COUNT_DRAWS=1 (with counting)
        // history only: the replay reads the depth the prepass left (PIXEL_HISTORY_DEPTH), in
        // either prepass_mode (prepass_inputs is gbuffer's only).
        bool after_prepass = false;
        // render_path=subpass with the G-buffer: normals and roughness come from input
        // attachments (SUBPASS_INPUTS=samples), set 4.
        bool gbuffer_inputs = false;
        bool operator==(const Variant&) const = default;
        size_t hash() const {
            return hash_fields(prepass_inputs, alpha_mask, non_invariant, counting, sample_shading,
                               alpha_to_coverage, history, int(samples), count_draws, after_prepass,
                               gbuffer_inputs);
        }
    };

    // The pipelines one recording draws with (made for its target): opaque, then MASK (with
    // the prepass and EQUAL the opaque one draws MASK too).
    struct Draw {
        Variant opaque, mask;
        bool with_mask = true;
        PipelineInfo opaque_info, mask_info;
        LightingInputs lighting;
        // What the sets are bound with (null: the pass's; the replay binds with its own, which
        // has set 4 too, or binding set 0 would disturb set 4).
        VkPipelineLayout layout = VK_NULL_HANDLE;
    };

    ShaderStages compile(const Variant& variant) const;
    vk::Pipeline create(const Variant& variant, const ShaderStages& stages,
                        const graph::RenderTarget& target) const;
    static std::string pipeline_name(const Variant& variant);
    // Its attachments and reads. render_path=subpass (seed 002's subpass 1): the light the
    // prepass cleared, the depth read-only, normals and roughness as input attachments.
    void declare(graph::PassBuilder& b, const FrameInputs& in, FrameResources& res,
                 const LightingInputs& lighting);
    void record(graph::PassContext& ctx, const FrameInputs& in, const FrameResources& res,
                const Draw& draw);
    // Binds the sets and draws opaque, then MASK, with `draw`'s pipelines, logged to `log`.
    void draw_scene(graph::PassContext& ctx, const FrameInputs& in, const Draw& draw,
                    VkDescriptorSet lighting, DrawLog* log);
    // Pixel history: the replay of draw_scene() with the instrumented twins of `draw`'s.
    void add_history(graph::RenderGraph& graph, const FrameInputs& in, const FrameResources& res,
                     const Draw& draw);
    bool native_resolve(const FrameOptions& o) const;
    // Set 4 of the subpass pipelines: the input attachments, written for this frame.
    VkDescriptorSet input_set(graph::PassContext& ctx, const FrameInputs& in,
                              const FrameResources& res);

    PassServices services_;
    bool invariant_ = true;  // this frame's (configure)
    LightingSet lighting_;
    // count_draws with prepass=off: forward decides visibility, so its draws are queried.
    GeometryInstrument instrument_;
    vk::PipelineLayout layout_;
    vk::DescriptorSetLayout input_layout_;  // set 4 of subpass_layout_
    vk::PipelineLayout subpass_layout_;     // layout_'s sets and the input attachments
    FrameDescriptorPool input_sets_;
    PipelineVariants<Variant> pipelines_;
};

}  // namespace ds::passes
