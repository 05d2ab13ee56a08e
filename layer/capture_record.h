#pragma once
// Recording the captured frame again, into the layer's own command buffers: the
// application's commands as they were, with each draw in a pass with a depth attachment
// drawn by its counting pipeline inside a precise occlusion query, then once more by its
// measurement pipeline (rasterized fragments). The application's descriptor sets that the
// layer's own bind disturbs are bound again after it (Vulkan's pipeline layout
// compatibility), and so are the dynamic depth and stencil switches it turns off.
#include <array>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "layer/capture_pipelines.h"
#include "layer/capture_resources.h"
#include "layer/depth_records.h"
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
    DepthUse depth;            // as drawn
    DrawGeometry geometry;
    bool depth_recorded = false;  // re-drawn for the depth records (zfight, equal_check)
    bool equal_counted = false;   // re-drawn by the EQUAL check
    int32_t equal_prepass = -1;   // the frame pass whose geometry it draws again
    std::string depth_why;        // why a depth-writing or EQUAL draw is not re-drawn
};

// A pass of the frame with depth-writing draws: what the EQUAL check matches later draws with.
struct DepthWritingPass {
    uint32_t pass = 0;  // in the frame
    VkImage image = VK_NULL_HANDLE;
    std::vector<std::pair<uint32_t, DrawGeometry>> draws;  // frame draw index, geometry
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
    // `bases`: the frame's passes and draws before this submission; `earlier`: its passes
    // with depth-writing draws so far (this submission's are added as they come).
    struct Bases {
        uint32_t pass = 0, draw = 0;
    };
    CountingRecorder(DeviceData& d, CountingPipelines& pipelines, CaptureResources& res,
                     const SubmissionPlan& plan, std::vector<std::string> labels, Bases bases,
                     std::vector<DepthWritingPass> earlier);
    // Records `cb`'s commands into `out` (begun by the caller); passes and draws continue
    // from the previous buffer's.
    void record(const CommandBufferState& cb, VkCommandBuffer out);
    std::vector<CapturedDraw>& draws() { return draws_; }
    const std::vector<DepthWritingPass>& depth_passes() const { return depth_passes_; }
    // Per pass of the submission: the prepass draws (frame indices) its EQUAL draws match.
    const std::map<uint32_t, std::set<uint32_t>>& equal_matches() const { return equal_matches_; }
    // The passes whose depth records were made (capture_record_depth.cpp), by submission pass.
    const std::map<uint32_t, bool>& recorded_passes() const { return pass_reverse_; }
    // Host-side set-up of the resources once recorded: draw ids, depth pass headers.
    void prepare(uint32_t zfight_steps);
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
    void begin_instance(bool resuming, bool suspending);
    void draw(const Command& c);
    void counted_draw(const Command& c, const CountingPipeline& p, CapturedDraw& draw);
    void use_pipeline(VkPipeline p);
    void restore_sets(uint32_t from);
    void set_dynamic_depth(const CountingPipeline& p, bool app_values);
    // capture_record_depth.cpp
    void bind_counters(VkPipelineLayout layout, const CapturedDraw& draw);
    void track_state(const Command& c);
    void depth_draw(const CountingPipeline& p, CapturedDraw& draw);
    void equal_draw(const Command& c, const CountingPipeline& p, CapturedDraw& draw);
    void end_render_pass_instance();
    void depth_phase(uint32_t pass, DepthMode mode);
    void depth_barrier();

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
    std::array<uint32_t, 5> dynamic_depth_{};     // DynamicDepthArgs::Which
    // Depth records and EQUAL check (capture_record_depth.cpp)
    const CommandBufferState* cb_ = nullptr;
    size_t command_ = 0;  // the index in cb_ of the command being recorded
    Bases bases_;
    std::vector<DepthWritingPass> depth_passes_;
    std::map<uint32_t, std::set<uint32_t>> equal_matches_;
    std::map<uint32_t, std::vector<std::pair<size_t, uint32_t>>> depth_draws_;  // command, slot
    std::map<uint32_t, bool> pass_reverse_;  // passes with depth records: nearer is larger
    std::optional<IndexBufferArgs> index_;
    std::map<uint32_t, std::pair<VkBuffer, VkDeviceSize>> vertex_;
    int instance_first_pass_ = 0;  // the render pass instance's first pass
    const CommandBufferState* instance_cb_ = nullptr;  // where it began
    bool suspending_ = false;      // the dynamic rendering under way suspends
    int pass_ = -1;
    bool in_pass_ = false;
    uint32_t draws_in_pass_ = 0;
    uint32_t app_queries_ = 0;  // the application's occlusion queries open
};

}  // namespace ds::layer
