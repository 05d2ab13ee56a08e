#pragma once
// forward: metallic-roughness PBR (GGX, Smith, Schlick) lit by the sun with PCF shadows and
// contact shadows, and a hemispherical ambient with material AO x GTAO, into the HDR image
// (R16G16B16A16_SFLOAT, cleared to the background colour; tonemap is its own pass).
//
// With the prepass: depth is loaded and never stored (STORE_OP_NONE, read-only layout), the
// test is EQUAL (or the closer-or-equal one with depth_compare=greater_or_equal), writes off,
// and normal and roughness come from the prepass images. With EQUAL no forward pipeline has
// a discard: EQUAL already keeps only what the masked prepass kept, so every one keeps
// early-Z. greater_or_equal would let the cut-out parts of MASK surfaces through (they are
// nearer than what the prepass kept), so there MASK keeps its alpha test, in its own pipeline.
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
// writes that depth and resolves it to the nearest sample into res.depth, natively or by
// DepthResolve after its rendering.
#include <array>
#include <cstdint>

#include <vulkan/vulkan.h>

#include "renderer/graph/graph.h"
#include "renderer/passes/depth_resolve.h"
#include "renderer/passes/frame.h"
#include "renderer/passes/lighting_set.h"
#include "renderer/passes/pass_util.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/destroy_list.h"
#include "renderer/vk/pipeline.h"

namespace ds::passes {

class ForwardPass {
  public:
    static constexpr const char* kName = "forward";
    static constexpr VkFormat kHdrFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
    // Linear radiance behind everything when the sky pass is off.
    static constexpr std::array<float, 4> kBackground = {0.25f, 0.42f, 0.85f, 1.0f};

    explicit ForwardPass(const PassServices& services);

    void rebuild_pipelines(vk::DestroyList& retired);
    // Creates res.hdr (msaa > 1: draws into res.msaa_hdr instead). Reads res.depth (writes it
    // without the prepass), res.shadow_map, res.normals, res.roughness, res.ao, res.contact_shadows
    // where valid. Counts into res.forward_counts when it is valid.
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res);

  private:
    // Variant key bits.
    static constexpr uint32_t kPrepassInputs = 1;  // PREPASS=1 (no discard)
    static constexpr uint32_t kAlphaMask = 2;      // ALPHA_MASK=1 (not with prepass + EQUAL)
    static constexpr uint32_t kNonInvariant = 4;   // invariant=off vertex shader
    static constexpr uint32_t kCounting = 8;
    static constexpr uint32_t kSampleShading = 16;    // sample_shading=on (msaa > 1)
    static constexpr uint32_t kAlphaToCoverage = 32;  // MASK pipelines, alpha_to_coverage=on
    // samples_key() holds bits 8-15.

    struct Draw {
        VkPipeline opaque = VK_NULL_HANDLE;  // with the prepass and EQUAL: opaque and MASK
        VkPipeline mask = VK_NULL_HANDLE;    // otherwise: MASK, with its discard
        LightingInputs lighting;
    };

    ShaderStages compile(uint32_t key) const;
    vk::Pipeline create(uint32_t key, const ShaderStages& stages) const;
    void declare(graph::PassBuilder& b, const FrameInputs& in, FrameResources& res,
                 const LightingInputs& lighting) const;
    void record(graph::PassContext& ctx, const FrameInputs& in, const FrameResources& res,
                const Draw& draw);
    void begin(graph::PassContext& ctx, const FrameOptions& o, const FrameResources& res) const;
    bool native_resolve(const FrameOptions& o) const;

    PassServices services_;
    LightingSet lighting_;
    vk::DescriptorSetLayout count_layout_;
    vk::PipelineLayout layout_;
    FrameDescriptorPool count_sets_;
    PipelineVariants pipelines_;
    DepthResolve resolve_;  // prepass=off with msaa > 1, without a native MAX / MIN
};

}  // namespace ds::passes
