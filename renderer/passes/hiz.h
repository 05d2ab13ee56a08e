#pragma once
// hiz (hiz=on, with the prepass): a Hi-Z pyramid from the prepass depth, and with
// count_draws=on a per-draw occlusion test against it (docs/history/issue-15.md).
//
// Graph pass "hiz" (compute, shaders/hiz.comp): images hiz.0 ... hiz.N (R32_SFLOAT, the frame's
// depth semantic so the viewer decodes them as depth), level 0 the prepass depth (at msaa > 1
// the farthest of each pixel's samples: a resolved depth keeps the nearest, which is not
// conservative), level k+1 max(1, floor(size / 2)) of level k, each texel the farthest
// (reverse-Z min, forward-Z max) of its 2x2 children, 3 wide (tall) on the last column (row)
// when the parent's size is odd, so nothing is lost; up to the 1x1 level.
//
// Graph pass "hiz_test" (count_draws=on, compute, shaders/hiz_test.comp): one invocation per
// scene instance, its world box (GpuScene::instance_bounds) against the pyramid, verdicts into
// a HostReadback buffer; collect() puts a HizResult (levels and per-group verdicts; the join
// after collection, frame/frame_joins.cpp, puts them next to samples_passed in the draws and
// counts unsafe disagreements) and its report.json section "hiz".
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include <nlohmann/json_fwd.hpp>

#include "renderer/passes/compute_kernel.h"
#include "renderer/passes/frame_pass.h"
#include "renderer/passes/hiz_verdict.h"
#include "renderer/settings/knob.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/image.h"
#include "renderer/vk/pipeline.h"

namespace ds {

// hiz_test's finding for one scene instance: the level it read, its box's nearest depth and
// the pyramid's farthest there (both 0 where the test said nothing: behind the eye, in front
// of the near plane, outside).
struct HizInstance {
    HizVerdict verdict = HizVerdict::Visible;
    uint32_t level = 0;
    float nearest = 0.0f, farthest = 0.0f;
};

// hiz=on (with the prepass): the pyramid's levels, level 0 first (images hiz.0 ... hiz.N);
// with count_draws=on also the per-group verdicts and, filled by the join, the unsafe
// disagreements: groups Hi-Z calls not visible (occluded or outside) whose samples_passed > 0.
struct HizResult {
    std::vector<std::pair<uint32_t, uint32_t>> levels;  // width, height
    std::string source;                                 // "depth" | "msaa_depth"
    uint32_t samples = 1;                               // of the source (farthest of them)
    bool reverse_z = true;                              // farthest: min; else max
    std::vector<HizVerdict> groups;                     // count_draws: per draw group
    std::vector<uint32_t> occluded_instances;           // count_draws: per draw group
    std::vector<HizInstance> instances;                 // count_draws: per scene instance
    std::optional<uint64_t> unsafe;                     // count_draws: see above
    // count_draws: groups Hi-Z calls not visible that won pixels in the final depth
    // (visible_pixels > 0): wrong whatever the draw order (samples_passed counts what passed
    // when drawn, so a layer drawn before its occluder passes samples and is still hidden).
    std::optional<uint64_t> unsafe_visible;
};

}  // namespace ds

namespace ds::passes {

// Its report.json section(s), put with the result (ResultSlots).
void hiz_report(const HizResult& result, const FrameResult& frame, nlohmann::json& report);

// The pyramid's level sizes for a `base` (level 0) size: level k+1 is max(1, floor(level k / 2))
// in each axis, down to 1x1.
std::vector<VkExtent2D> hiz_level_extents(VkExtent2D base);
// "hiz.K", the graph image of level k.
std::string hiz_level_name(uint32_t level);

class HizPass final : public FramePass {
  public:
    static constexpr VkFormat kFormat = VK_FORMAT_R32_SFLOAT;
    // Levels hiz_test binds (a 32768-wide frame has 16); a bigger frame is refused.
    static constexpr uint32_t kMaxLevels = 16;
    // hiz_test calls a box occluded only when it is farther than the pyramid's farthest by more
    // than this fraction of the larger depth value (rounding between its transform and the
    // rasteriser's).
    static constexpr float kMargin = 1e-5f;

    explicit HizPass(const PassServices& services);

    static constexpr Knob<bool> kKnob{"hiz"};
    static std::vector<SettingDef> knobs();

    const char* name() const override { return "hiz"; }
    void configure(const FrameSetup& setup, FrameOptions& options) override;
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) override;
    void rebuild_pipelines(vk::DestroyList& retired) override;
    void collect(const FrameCollect& c, std::span<PassResult> own, FrameResult& frame) override;

  private:
    std::vector<graph::ImageHandle> add_pyramid(graph::RenderGraph& graph, const FrameInputs& in,
                                                const FrameResources& res);
    void add_test(graph::RenderGraph& graph, const FrameInputs& in, const FrameResources& res,
                  const std::vector<graph::ImageHandle>& levels);
    void record_test(graph::PassContext& ctx, VkDescriptorSet frame_set, uint32_t instances,
                     uint32_t levels);
    void build_kernels();
    void install_kernels(vk::DestroyList& retired);

    PassServices services_;
    ComputeKernel copy_, copy_samples_, reduce_;
    bool built_ = false;
    // hiz_test: set 1 = boxes, verdicts, the levels; one set (Renderer::render waits for each
    // frame before recording the next, as HostReadback relies on).
    vk::Sampler nearest_;
    vk::DescriptorSetLayout test_set_layout_;
    vk::DescriptorPool test_pool_;
    VkDescriptorSet test_set_ = VK_NULL_HANDLE;
    vk::PipelineLayout test_layout_;
    LazyComputePipeline test_pipeline_;
    // This frame's.
    bool on_ = false;  // hiz=on, with the prepass, on the dynamic path
    std::optional<HizResult> result_;
    graph::BufferHandle verdicts_;
};

}  // namespace ds::passes
