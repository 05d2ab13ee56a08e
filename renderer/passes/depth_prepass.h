#pragma once
// depth_prepass (seed 000): fills the scene depth before anything is lit. Depth: the frame's
// depth_format (D32 unless set), cleared to "far", the closer test (GREATER with reverse-Z),
// writes on. prepass_mode=gbuffer (default) also writes the world-space shading normal
// (A2B10G10R10, n * 0.5 + 0.5, normal-mapped) and the roughness (R8) that forward, GTAO and
// contact shadows read. prepass_mode=depth is the classic Z-only prepass (seeds 003 / 004): no
// colour attachment, and the opaque pipeline has no fragment stage and fetches positions
// only; the MASK pipeline keeps a fragment shader for its alpha test and writes nothing.
// A diagnostic that needs a fragment shader (counting, surface_id, pixel history) gives the
// opaque pipeline one that does only that, as the shadow pass does. With alpha_to_coverage the
// coverage alpha goes to colour slot 0, which has no image (alpha to coverage reads output 0
// whatever is bound; writes to it are discarded).
//
// Two pipelines share the invariant vertex shader: opaque first (no discard: early-Z is
// guaranteed), then MASK (alpha test before any other texture read). masked_split=off draws
// all geometry with one pipeline that has the discard, to show what losing early-Z costs.
// BLEND materials are not drawn here. Cull mode follows each draw group.
//
// msaa > 1: renders into multisampled depth (res.msaa_depth, STOREd: forward LOADs it),
// normals and roughness; normals and roughness resolve inline (AVERAGE) into the
// single-sample images; depth resolves to the nearest sample, natively (MAX / MIN resolve
// attachment) where the device has the mode, else in the depth_resolve pass that follows.
//
// alpha_to_coverage=on (msaa > 1): the pipeline with the alpha test writes a sharpened alpha
// to output 0 (normals) and alpha-to-coverage cuts samples instead of the discard.
// surface_id (knob surface_id, or zfight): a third attachment, R32_UINT res.surface_id, the
// winning surface per pixel (at msaa > 1 resolved SAMPLE_ZERO, as integers must be; the
// samples, res.msaa_surface_id, are STOREd for the sample view and zfight).
// alpha_mip (knob alpha_mip, dynamic path only): one more attachment after those, image
// `alpha_mip` (R32_SFLOAT): per pixel the mip level of the base colour that the winning MASK
// surface's alpha test sampled (textureQueryLod, 0 with alpha_level0), -1 where the winner is
// not MASK or nothing was drawn; a Scalar shown on a heat scale (kAlphaMipDisplay). At
// msaa > 1 the samples average, as normals and roughness do (AVERAGE resolve: a float), so a
// pixel whose samples hold a MASK surface and another lies between -1 and the level.
//
// count_draws=on: the prepass decides visibility, so each of its draws is inside a precise
// occlusion query (DrawQueries; samples_passed per draw group).
//
// count_discards=on: that pipeline counts the fragments it ran and those it discarded into a
// small host storage buffer (set 2, HostReadback), read after the frame's fence.
// Pixel history (FrameInputs::pixel): depth_prepass_history replays draw_scene() first with
// the instrumented variants (pixel_history.h); its fragments start from the cleared depth.
// Counts, the measurement draw, the replay, the queries and the pipeline records are the
// GeometryInstrument's (geometry_instrument.h).
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include <vulkan/vulkan.h>

#include <nlohmann/json_fwd.hpp>

#include "renderer/graph/graph.h"
#include "renderer/passes/frame.h"
#include "renderer/passes/frame_pass.h"
#include "renderer/passes/geometry_instrument.h"
#include "renderer/passes/pass_util.h"
#include "renderer/settings/knob.h"
#include "renderer/vk/buffer.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/destroy_list.h"
#include "renderer/vk/pipeline.h"

namespace ds {

// count_discards=on: fragments that ran the depth prepass's alpha-tested pipeline (the MASK one;
// masked_split=off: the one for all geometry), and how many of them it discarded. Exact
// (shader atomics; helper invocations do not count).
struct DiscardCounts {
    uint64_t invoked = 0;
    uint64_t discarded = 0;
};

}  // namespace ds

namespace ds::passes {

// Its report.json section(s), put with the result (ResultSlots).
void discards_report(const DiscardCounts& result, const FrameResult& frame, nlohmann::json& report);

class DepthPrepass final : public FramePass {
  public:
    static constexpr const char* kName = "depth_prepass";
    static constexpr VkFormat kNormalFormat = VK_FORMAT_A2B10G10R10_UNORM_PACK32;
    static constexpr VkFormat kRoughnessFormat = VK_FORMAT_R8_UNORM;
    static constexpr VkFormat kSurfaceFormat = VK_FORMAT_R32_UINT;
    static constexpr VkFormat kAlphaMipFormat = VK_FORMAT_R32_SFLOAT;
    static constexpr float kAlphaMipNone = -1.0f;  // alpha_mip where no MASK surface won
    // prepass_mode=depth with alpha_to_coverage: the pipelines' format for colour slot 0, which
    // the rendering leaves without an image.
    static constexpr VkFormat kCoverageSlotFormat = VK_FORMAT_R8_UNORM;

    explicit DepthPrepass(const PassServices& services);

    const char* name() const override { return kName; }
    static constexpr Knob<bool> kMaskedSplit{"masked_split"};
    static constexpr Knob<bool> kPrepassSort{"prepass_sort"};
    static constexpr Knob<bool> kSurfaceId{"surface_id"};
    static constexpr Knob<bool> kCountDiscards{"count_discards"};
    static constexpr Knob<bool> kAlphaMip{"alpha_mip"};
    static std::vector<SettingDef> knobs();
    void configure(const FrameSetup& setup, FrameOptions& options) override;
    // surface_id: on when asked for (its knob, zfight, equal_check, count_draws, the sample
    // view), with the prepass, on the dynamic path.
    void resolve(FrameOptions& options) override;
    void rebuild_pipelines(vk::DestroyList& retired) override;
    // Writes res.depth (which the renderer provides; at msaa > 1 without a native resolve,
    // res.msaa_depth and depth_resolve follows); creates res.normals and res.roughness.
    // Counts into res.prepass_counts when it is valid.
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) override;
    // shaded_fragments from res.prepass_counts; DiscardCounts (report "masked_discards").
    void collect(const FrameCollect& c, std::span<PassResult> own, FrameResult& frame) override;

  private:
    // The shader's ALPHA_MASK: none (opaque), MASK materials, or all geometry (unsplit).
    enum class AlphaTest : uint8_t { Opaque = 0, Mask = 1, Unsplit = 2 };
    struct Variant {
        AlphaTest alpha = AlphaTest::Opaque;
        bool counting = false;           // COUNT_FRAGMENTS=1
        bool alpha_to_coverage = false;  // alpha-tested pipeline only
        bool count_discards = false;     // alpha-tested pipeline only
        bool surface_id = false;         // SURFACE_ID=1: a u32 attachment after the others
        bool alpha_mip = false;          // ALPHA_MIP=1: a float attachment after surface_id
        bool history = false;            // PIXEL_HISTORY=1: the replay's, no attachments
        VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
        bool count_draws = false;    // COUNT_DRAWS=1 (with counting)
        bool gbuffer = true;         // prepass_mode=gbuffer: normals, roughness
        bool coverage_slot = false;  // depth mode, alpha_to_coverage: colour slot 0, no image
        // render_path=subpass: LIGHT_SLOT=1, the light is colour attachment 0 (the surface's
        // emission, none, and alpha-to-coverage's alpha).
        bool light_slot = false;
        bool operator==(const Variant&) const = default;
        size_t hash() const {
            return hash_fields(int(alpha), counting, alpha_to_coverage, count_discards, surface_id,
                               history, int(samples), count_draws, gbuffer, coverage_slot,
                               light_slot, alpha_mip);
        }
    };
    // Whether the variant has a fragment stage: prepass_mode=depth's plain opaque one has none.
    static bool has_fragment_stage(const Variant& v);
    static constexpr uint32_t kDiscardSet = 2;

    // The pipelines one recording draws with: the opaque and alpha-tested variants (unsplit:
    // `opaque` is the one with the alpha test and `mask` is unused), made for the target.
    struct Draw {
        Variant opaque, mask;
        bool split = true;
        PipelineInfo opaque_info, mask_info;
        VkDescriptorSet discards = VK_NULL_HANDLE;
        // What the sets are bound with (null: the pass's; the replay binds with its own, which
        // has set 4 too, or binding set 0 would disturb set 4).
        VkPipelineLayout layout = VK_NULL_HANDLE;
    };

    ShaderStages compile(const Variant& variant) const;
    vk::Pipeline create(const Variant& variant, const ShaderStages& stages,
                        const graph::RenderTarget& target) const;
    static std::string pipeline_name(const Variant& variant);

    // The pass's attachments and reads (depth_prepass_attachments.cpp). Dynamic path: depth,
    // normals and roughness (resolved inline at msaa > 1), surface_id. render_path=subpass
    // (seed 002's subpass 0): the light first (res.hdr, or res.msaa_hdr), cleared; normals and
    // roughness multisampled at msaa > 1 and never resolved (forward reads every sample as an
    // input attachment); the depth resolves after the render pass (depth_resolve).
    void declare(graph::PassBuilder& b, const FrameInputs& in, FrameResources& res);
    void declare_tiled(graph::PassBuilder& b, const FrameInputs& in, FrameResources& res);
    // declare()'s multisampled attachments and their resolves.
    void declare_samples(graph::PassBuilder& b, const FrameInputs& in, FrameResources& res,
                         const graph::DepthUse& depth);
    // The frame's pipelines: the opaque and alpha-tested variants (or the one unsplit one).
    Draw make_draw(const Variant& opaque, const Variant& tested, bool split);
    VkDescriptorSet discard_set(graph::PassContext& ctx, const FrameInputs& in,
                                graph::BufferHandle buffer);
    void record(graph::PassContext& ctx, const FrameInputs& in, Draw draw,
                graph::BufferHandle discards);
    // The pass's draws with `draw`'s pipelines (the frame's or the replay's), logged to `log`.
    void draw_scene(graph::PassContext& ctx, const FrameInputs& in, const Draw& draw, DrawLog* log);
    // Pixel history: the replay of draw_scene() with the instrumented twins of `draw`'s.
    void add_history(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res,
                     const Draw& draw);

    PassServices services_;
    // This frame's options (configure).
    bool masked_split_ = true, prepass_sort_ = true, count_discards_ = false, alpha_mip_ = false;
    vk::DescriptorSetLayout discard_layout_;
    GeometryInstrument instrument_;
    vk::PipelineLayout layout_;
    FrameDescriptorPool discard_sets_;
    PipelineVariants<Variant> pipelines_;
    graph::BufferHandle discards_;  // this frame's discard counters (count_discards=on)
};

}  // namespace ds::passes
