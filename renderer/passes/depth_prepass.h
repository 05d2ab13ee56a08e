#pragma once
// depth_prepass (seed 000): fills the scene depth before anything is lit, and writes the
// world-space shading normal (A2B10G10R10, n * 0.5 + 0.5, normal-mapped) and the roughness
// (R8) that forward, GTAO and contact shadows read. Depth: D32, cleared to "far", the closer
// test (GREATER with reverse-Z), writes on.
//
// Two pipelines share the invariant vertex shader: opaque first (no discard: early-Z is
// guaranteed), then MASK (alpha test before any other texture read). masked_split=off draws
// all geometry with one pipeline that has the discard, to show what losing early-Z costs.
// BLEND materials are not drawn here. Cull mode follows each draw group.
//
// msaa > 1: renders into multisampled depth (res.msaa_depth, STOREd: forward LOADs it),
// normals and roughness; normals and roughness resolve inline (AVERAGE) into the
// single-sample images; depth resolves to the nearest sample, natively (MAX / MIN resolve
// attachment) where the device has the mode, else by DepthResolve after the rendering, in
// this same pass.
//
// alpha_to_coverage=on (msaa > 1): the pipeline with the alpha test writes a sharpened alpha
// to output 0 (normals) and alpha-to-coverage cuts samples instead of the discard.
// count_discards=on: that pipeline counts the fragments it ran and those it discarded into a
// small storage buffer (set 2), read back after the frame's fence.
#include <array>
#include <cstdint>
#include <optional>

#include <vulkan/vulkan.h>

#include "renderer/graph/graph.h"
#include "renderer/passes/depth_resolve.h"
#include "renderer/passes/frame.h"
#include "renderer/passes/pass_util.h"
#include "renderer/vk/buffer.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/destroy_list.h"
#include "renderer/vk/pipeline.h"

namespace ds::passes {

// count_discards=on: fragments that ran the prepass alpha test, and those it discarded.
struct DiscardCounts {
    uint64_t invoked = 0;
    uint64_t discarded = 0;
};

class DepthPrepass {
  public:
    static constexpr const char* kName = "depth_prepass";
    static constexpr VkFormat kNormalFormat = VK_FORMAT_A2B10G10R10_UNORM_PACK32;
    static constexpr VkFormat kRoughnessFormat = VK_FORMAT_R8_UNORM;

    explicit DepthPrepass(const PassServices& services);

    void rebuild_pipelines(vk::DestroyList& retired);
    // Writes res.depth (which the renderer provides); creates res.normals and res.roughness.
    // Counts into res.prepass_counts when it is valid.
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res);
    // After frame `frame_number`'s fence: its discard counts, if that frame counted them.
    std::optional<DiscardCounts> discard_counts(uint64_t frame_number) const;

  private:
    // Variant key: the alpha test (bits 0-1, the shader's ALPHA_MASK), counting (bit 2),
    // samples_key() (bits 8-15).
    enum AlphaTest : uint32_t { kOpaque = 0, kMask = 1, kUnsplit = 2 };
    static constexpr uint32_t kCounting = 4;
    static constexpr uint32_t kAlphaToCoverage = 8;  // alpha-tested pipeline only
    static constexpr uint32_t kCountDiscards = 16;   // alpha-tested pipeline only
    static constexpr uint32_t kDiscardSet = 2;

    struct Draw {
        VkPipeline opaque = VK_NULL_HANDLE;  // unsplit: the one pipeline
        VkPipeline mask = VK_NULL_HANDLE;    // unsplit: null
        VkDescriptorSet counts = VK_NULL_HANDLE;
        VkDescriptorSet discards = VK_NULL_HANDLE;
    };
    // count_discards=on: one host-readable buffer per frame in flight.
    struct DiscardSlot {
        vk::Buffer buffer;
        uint64_t frame = UINT64_MAX;  // the frame that last counted into it
    };

    ShaderStages compile(uint32_t key) const;
    vk::Pipeline create(uint32_t key, const ShaderStages& stages) const;
    // msaa > 1: the multisampled normals and roughness (transients) of this frame.
    struct Msaa {
        graph::ImageHandle normals, roughness;
    };

    Msaa declare(graph::PassBuilder& b, const FrameInputs& in, FrameResources& res) const;
    graph::BufferHandle import_discards(graph::RenderGraph& graph, uint64_t frame_number);
    VkDescriptorSet prepare_discards(graph::PassContext& ctx, const FrameInputs& in,
                                     graph::BufferHandle buffer);
    void record(graph::PassContext& ctx, const FrameInputs& in, const FrameResources& res,
                const Msaa& msaa, Draw draw, graph::BufferHandle discards);
    void begin(graph::PassContext& ctx, const FrameInputs& in, const FrameResources& res,
               const Msaa& msaa) const;
    void draw_scene(VkCommandBuffer cmd, const FrameInputs& in, Draw draw) const;

    PassServices services_;
    vk::DescriptorSetLayout discard_layout_;
    vk::DescriptorSetLayout count_layout_;
    vk::PipelineLayout layout_;
    FrameDescriptorPool count_sets_;
    FrameDescriptorPool discard_sets_;
    std::array<DiscardSlot, vk::FrameRing::kFramesInFlight> discard_slots_;
    PipelineVariants pipelines_;
    DepthResolve resolve_;
};

}  // namespace ds::passes
