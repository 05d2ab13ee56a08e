#pragma once
// Recording the captured frame again, into the layer's own command buffers: the
// application's commands as they were, with each draw in a pass with a depth attachment
// drawn by its counting pipeline inside a precise occlusion query, then once more by its
// measurement pipeline (rasterized fragments). The application's descriptor sets that the
// layer's own bind disturbs are bound again after it (Vulkan's pipeline layout
// compatibility), and so are the dynamic depth and stencil switches it turns off.
#include <array>
#include <string>
#include <vector>

#include "layer/capture_pipelines.h"
#include "layer/capture_resources.h"
#include "layer/state.h"
#include "layer/summary.h"

namespace ds::layer {

struct CapturedDraw {
    uint32_t pass = 0;  // index into the frame's passes
    uint32_t index_in_pass = 0;
    std::vector<std::string> labels;  // open debug-utils labels, outermost first
    VkPipeline pipeline = VK_NULL_HANDLE;
    DrawArgs args{};
    std::string not_analysed;  // empty: counted
    uint32_t slot = 0;         // its counters and query in this submission's resources
    bool queried = false;
};

// What a submission's walk over its command buffers finds, in order, before anything is
// recorded: the passes (sizes for the pixel counters) and the draws in depth passes.
struct SubmissionPlan {
    std::vector<PassSummary> passes;
    std::vector<bool> pass_counted;  // a depth attachment, single view
    uint32_t counted_draws = 0;
};
SubmissionPlan plan_submission(DeviceData& d, const std::vector<const CommandBufferState*>& cbs);

class CountingRecorder {
  public:
    CountingRecorder(DeviceData& d, CountingPipelines& pipelines, CaptureResources& res,
                     const SubmissionPlan& plan, std::vector<std::string> labels);
    // Records `cb`'s commands into `out` (begun by the caller); passes and draws continue
    // from the previous buffer's.
    void record(const CommandBufferState& cb, VkCommandBuffer out);
    std::vector<CapturedDraw>& draws() { return draws_; }
    std::vector<std::string> notes;  // not_analysed entries found while recording

  private:
    struct BoundSet {
        VkPipelineLayout layout = VK_NULL_HANDLE;
        VkDescriptorSet set = VK_NULL_HANDLE;
        std::vector<uint32_t> offsets;
        bool valid = false;
    };
    void step(const Command& c);
    void bind_sets(const BindSetsArgs& a);
    bool compatible(VkPipelineLayout a, VkPipelineLayout b, uint32_t set);
    void begin_pass(bool dynamic_resume);
    void draw(const Command& c);
    void counted_draw(const Command& c, const CountingPipeline& p, CapturedDraw& draw);
    void use_pipeline(VkPipeline p);
    void restore_sets(uint32_t from);
    void set_dynamic_depth(const CountingPipeline& p, bool app_values);

    DeviceData& d_;
    CountingPipelines& pipelines_;
    CaptureResources& res_;
    const SubmissionPlan& plan_;
    VkCommandBuffer out_ = VK_NULL_HANDLE;
    std::vector<CapturedDraw> draws_;
    std::vector<std::string> labels_;
    std::array<BoundSet, 32> sets_{};
    VkPipeline app_pipeline_ = VK_NULL_HANDLE;    // what the application bound
    VkPipeline bound_pipeline_ = VK_NULL_HANDLE;  // what the layer has bound
    std::array<VkBool32, 4> dynamic_depth_{};     // DynamicDepthArgs::Which
    int pass_ = -1;
    bool in_pass_ = false;
    uint32_t draws_in_pass_ = 0;
    uint32_t app_queries_ = 0;  // the application's occlusion queries open
};

}  // namespace ds::layer
