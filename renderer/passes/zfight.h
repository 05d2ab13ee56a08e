#pragma once
// zfight (zfight=on, with the prepass): the Z-fight detector. Opaque and masked geometry is
// drawn again over the prepass result without a depth test; every fragment of another
// surface than the pixel's winner (res.surface_id) that passes its alpha test and lies
// within zfight_steps representable depth steps of the stored depth (D32_SFLOAT: ULPs; D24 /
// D16: unorm steps) competes (shaders/zfight.frag). Image res.zfight (created and zeroed by
// clear_counts) holds competitors per pixel; a host buffer of (pixel, winner, competitor,
// steps) records becomes FrameResult::zfight's pairs. A surface is one triangle of one
// instance, so overlapping triangles of one mesh fight too, and triangles that share an
// edge never do (each pixel centre belongs to one of them). It needs the prepass and msaa=1
// (a multisampled depth is stored at sample positions, not at the centre it compares at).
#include <bit>
#include <cstdint>

#include <vulkan/vulkan.h>

#include "renderer/passes/frame_pass.h"
#include "renderer/passes/pass_util.h"
#include "renderer/passes/pipeline_use.h"
#include "renderer/passes/zfight_bound.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/image.h"
#include "renderer/vk/pipeline.h"

namespace ds {
struct SurfaceTable;
}

namespace ds::passes {

// One competitor as the shader appends it (std430 uvec4).
struct ZfightRecord {
    static constexpr uint32_t kStepsMask = 0x7ff;  // zfight_steps <= 1024
    uint32_t pixel = 0;                            // y * width + x
    uint32_t winner = 0, competitor = 0;           // surface ids
    // The gap in scene units along the view ray, a float whose low 11 mantissa bits hold the
    // gap in depth steps instead.
    uint32_t gap_and_steps = 0;
    uint32_t steps() const { return gap_and_steps & kStepsMask; }
    float gap() const { return std::bit_cast<float>(gap_and_steps & ~kStepsMask); }
};
static_assert(sizeof(ZfightRecord) == 16);

// The pairs of instances the records name (by SurfaceTable), each with its distinct pixels
// and smallest gap, most pixels first. Records naming no surface are skipped.
ZfightResult zfight_pairs(std::span<const ZfightRecord> records, const SurfaceTable& table);

class ZfightPass final : public FramePass {
  public:
    explicit ZfightPass(const PassServices& services);

    const char* name() const override { return "zfight"; }
    std::optional<std::string> skipped(const FrameInputs& in) const override;
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) override;
    void rebuild_pipelines(vk::DestroyList& retired) override {
        pipelines_.rebuild(retired);
        bound_.rebuild_pipelines(retired);
    }
    // FrameResult::zfight: the competing pixels and the pairs of surfaces, by pixels.
    void collect(const FrameCollect& c, std::span<PassResult> own, FrameResult& frame) override;

  private:
    struct Bound {
        graph::ImageHandle surfaces, depth, limit, competitors;  // limit: ZfightBound's
        graph::BufferHandle records;
    };
    using Variant = DepthFormatVariant;  // the frame's depth_format (the limit's)
    ShaderStages compile(const Variant& variant) const;
    vk::Pipeline create(const Variant& variant, const ShaderStages& stages) const;
    void record(graph::PassContext& ctx, const FrameInputs& in, const Bound& bound);

    PassServices services_;
    vk::Sampler nearest_;
    vk::DescriptorSetLayout set_layout_;
    vk::PipelineLayout layout_;
    FrameDescriptorPool sets_;
    PipelineVariants<Variant> pipelines_;
    ZfightBound bound_;
    graph::BufferHandle records_;  // this frame's, if it ran
    PipelineUses uses_;            // this frame's
    uint32_t capacity_ = 0;
};

}  // namespace ds::passes
