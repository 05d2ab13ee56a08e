#pragma once
// hiz (hiz=on, with the prepass): a Hi-Z pyramid from the prepass depth, and with
// count_draws=on a per-draw occlusion test against it (DESIGN "As built (issue 15: Hi-Z)").
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
// a HostReadback buffer; collect() gives FrameResult::hiz (levels and per-group verdicts;
// readback_draws puts them next to samples_passed and counts unsafe disagreements).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/passes/compute_kernel.h"
#include "renderer/passes/frame_pass.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/image.h"
#include "renderer/vk/pipeline.h"

namespace ds::passes {

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

    const char* name() const override { return "hiz"; }
    std::optional<std::string> skipped(const FrameInputs& in) const override;
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
    std::optional<HizResult> result_;
    graph::BufferHandle verdicts_;
};

}  // namespace ds::passes
