#pragma once
// zfight (zfight=on, with the prepass): the Z-fight detector. Opaque and masked geometry is
// drawn again over the prepass result, tested early against zfight_bound (the stored depth
// moved zfight_steps + 1 steps towards far); every fragment of another surface than the
// pixel's winner (res.surface_id) that passes its alpha test and lies within zfight_steps
// representable depth steps of the stored depth (D32_SFLOAT: ULPs; D24 / D16: unorm steps)
// competes (shaders/zfight.frag). Image res.zfight (created and zeroed by clear_counts) holds
// competitors per pixel; a host buffer of (pixel, winner, competitor, steps) records becomes
// ZfightResult's pairs. A surface is one triangle of one instance, so overlapping
// triangles of one mesh fight too, and triangles that share an edge never do (each pixel
// centre, or sample, belongs to one of them). It needs the prepass.
// msaa > 1: it compares per sample. The pass runs multisampled against a multisampled bound
// with sample shading (the device's sampleRateShading, else skipped), and each sample's
// fragment is compared with that sample's stored depth (res.msaa_depth) and winner
// (res.msaa_surface_id, which the prepass then STOREs): the competitor image sums competing
// samples per pixel; a pair's pixels are the distinct pixels where it fights in any sample.
#include <bit>
#include <cstdint>

#include <vulkan/vulkan.h>

#include <nlohmann/json_fwd.hpp>

#include "renderer/common/surface_name.h"
#include "renderer/passes/frame_pass.h"
#include "renderer/passes/pass_util.h"
#include "renderer/passes/pipeline_use.h"
#include "renderer/passes/zfight_bound.h"
#include "renderer/settings/knob.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/image.h"
#include "renderer/vk/pipeline.h"

namespace ds {
struct SurfaceTable;
}

namespace ds {

// zfight=on: two instances whose surfaces fight, how many pixels they fight in and the
// smallest gap seen, in representable depth steps.
struct ZfightPair {
    SurfaceName a, b;  // a: the one with the lower instance index (a == b: within one mesh)
    uint64_t pixels = 0;
    uint32_t min_steps = 0;
};
// One pair fighting in one pixel (the least gap seen there).
struct ZfightHit {
    uint32_t pixel = 0;  // y * width + x
    uint32_t pair = 0;   // index into ZfightResult::pairs
    uint32_t steps = 0;
    float gap = 0;  // the same gap in scene units, along the pixel's view ray
};
struct ZfightResult {
    uint32_t steps = 0;             // zfight_steps
    uint64_t pixels = 0;            // pixels with at least one competitor
    std::vector<ZfightPair> pairs;  // most pixels first
    std::vector<ZfightHit> hits;    // by pixel, then pair: what the viewer highlights and reads
    uint64_t dropped = 0;           // competitor records past the buffer (pairs undercount)
};

}  // namespace ds

namespace ds::passes {

// Its report.json section(s), put with the result (ResultSlots).
void zfight_report(const ZfightResult& result, const FrameResult& frame, nlohmann::json& report);

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

    static constexpr Knob<bool> kKnob{"zfight"};
    static constexpr Knob<int> kSteps{"zfight_steps"};
    static std::vector<SettingDef> knobs();

    const char* name() const override { return "zfight"; }
    void configure(const FrameSetup& setup, FrameOptions& options) override;
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) override;
    void rebuild_pipelines(vk::DestroyList& retired) override {
        pipelines_.rebuild(retired);
        bound_.rebuild_pipelines(retired);
    }
    // A ZfightResult (report "zfight"): the competing pixels and the pairs of surfaces.
    void collect(const FrameCollect& c, std::span<PassResult> own, FrameResult& frame) override;

  private:
    struct Bound {
        graph::ImageHandle surfaces, depth, limit, competitors;  // limit: ZfightBound's
        graph::BufferHandle records;
    };
    using Variant = ZfightVariant;  // the frame's depth_format and msaa (the limit's)
    ShaderStages compile(const Variant& variant) const;
    vk::Pipeline create(const Variant& variant, const ShaderStages& stages,
                        const graph::RenderTarget& target) const;
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
    uint32_t steps_ = 4;  // zfight_steps, this frame's
};

}  // namespace ds::passes
