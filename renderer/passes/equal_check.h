#pragma once
// equal_check (equal_check=on; prepass on, depth_compare=equal, msaa=1): after forward, one
// compute dispatch (shaders/equal_check.comp) over forward's per-pixel fragment counts, the
// prepass depth and surface_id. Image `equal_check` (R32_UINT): 1 where the prepass covered
// the pixel and forward shaded nothing (a hole: invariance, jitter or cutoff mismatch), 2
// where forward shaded more than once (a tie: coplanar surfaces both passing EQUAL).
// An EqualCheckResult counts both and names the surfaces most involved. It turns on
// count_fragments (the counts) and surface_id (the names).
#include <cstdint>

#include <vulkan/vulkan.h>

#include <nlohmann/json_fwd.hpp>

#include "renderer/common/surface_name.h"
#include "renderer/passes/compute_kernel.h"
#include "renderer/passes/frame_pass.h"
#include "renderer/settings/knob.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/image.h"
#include "renderer/vk/pipeline.h"

namespace ds {

// equal_check=on: pixels the prepass covered that forward did not shade (holes) and pixels
// forward shaded more than once (multiple), and the instances most involved.
struct EqualCheckSurface {
    SurfaceName name;
    uint64_t holes = 0, multiple = 0;  // pixels it won in the prepass
};
struct EqualCheckResult {
    uint64_t holes = 0, multiple = 0;
    std::vector<EqualCheckSurface> surfaces;  // most pixels first, at most ten
};

}  // namespace ds

namespace ds::passes {

// Its report.json section(s), put with the result (ResultSlots).
void equal_check_report(const EqualCheckResult& result, const FrameResult& frame,
                        nlohmann::json& report);

class EqualCheckPass final : public FramePass {
  public:
    explicit EqualCheckPass(const PassServices& services);

    const char* name() const override { return "equal_check"; }
    static constexpr Knob<bool> kKnob{"equal_check"};
    static std::vector<SettingDef> knobs();
    void configure(const FrameSetup& setup, FrameOptions& options) override;
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) override;
    void rebuild_pipelines(vk::DestroyList& retired) override;
    void collect(const FrameCollect& c, std::span<PassResult> own, FrameResult& frame) override;

  private:
    struct Bound {
        graph::ImageHandle counts, depth, surfaces, marks;
        graph::BufferHandle result;
    };
    void record(graph::PassContext& ctx, const Bound& bound, float far_depth);

    PassServices services_;
    vk::Sampler nearest_;
    vk::DescriptorSetLayout set_layout_;
    vk::DescriptorPool pool_;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    vk::PipelineLayout layout_;
    LazyComputePipeline pipeline_;  // built by the first frame that checks
    bool on_ = false;               // this frame's (configure)
    graph::BufferHandle result_;
    uint32_t capacity_ = 0;
};

}  // namespace ds::passes
