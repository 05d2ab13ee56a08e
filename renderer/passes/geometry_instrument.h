#pragma once
// What every geometry pass (shadow, depth_prepass, forward, decals, transparent) measures about
// its own draws, as one component the pass owns (a pass never includes another pass):
//
// - count images (count_fragments=on): set 3 of the pass's pipeline layout, declared in its
//   setup, written and bound when it records; collect() reads the totals back;
// - the measurement draw ("<pass>_rasterized", rasterized_count.h), after the pass;
// - the pixel-history replay ("<pass>_history", pixel_history.h), before the pass;
// - occlusion queries (count_draws: the pass that decides visibility), reset before the
//   pass's rendering begins;
// - pipeline-use records: which pipelines drew how many draws this frame.
//
// The pass's layout is {frame, material, its set 2, the count set} (sets()); the replay's
// repeats those sets, so what the pass's drawing code binds stays bound for it.
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/graph/graph.h"
#include "renderer/passes/draw_queries.h"
#include "renderer/passes/frame.h"
#include "renderer/passes/frame_pass.h"
#include "renderer/passes/pass_util.h"
#include "renderer/passes/pipeline_use.h"
#include "renderer/passes/pixel_history.h"
#include "renderer/passes/rasterized_count.h"
#include "renderer/passes/scene_draw.h"
#include "renderer/vk/descriptors.h"

namespace ds::passes {

class GeometryInstrument {
  public:
    // `set2`: the pass's own set 2 (an empty layout where it has none).
    GeometryInstrument(const PassServices& services, const char* pass, VkDescriptorSetLayout set2);

    // The pass's pipeline layout's sets: frame, material, set 2, counts.
    std::vector<VkDescriptorSetLayout> sets() const;

    // The start of the pass's add(): forgets the last frame. `counts`: this frame's count images
    // (invalid: not counting); `queries`: occlusion queries around up to `max_draws` draws.
    void begin_frame(const CountImages& counts, bool queries, uint32_t max_draws);
    // In the pass's setup: its count images, and the query reset before its rendering.
    void declare(graph::PassBuilder& b);
    // In the pass's record: the count set, written and bound at set 3 of `layout`.
    void bind_counts(graph::PassContext& ctx, uint64_t frame_number, VkPipelineLayout layout);
    // What the frame's draws hand to draw_groups / draw_sorted (the queries); a replay's
    // (`log`) are logged, not queried.
    DrawHooks hooks(DrawLog* log = nullptr) { return {log ? nullptr : &queries_, log}; }
    // `draws` more with `info`'s pipeline this frame (a replay's draws are not the frame's).
    void used(const PipelineInfo& info, uint32_t draws) { uses_.add(info, draws); }

    // Pixel history: the replay's graph pass (pixel_history.h), before the pass's own.
    // `pipelines` are the pass's real ones, by the log's tags.
    PixelHistoryReplay& replay() { return history_; }
    const PixelHistoryReplay& replay() const { return history_; }
    void add_history(graph::RenderGraph& graph, const FrameInputs& in,
                     const PixelHistoryReplay::Reads& reads, PixelHistoryReplay::Declare declare,
                     PixelHistoryReplay::Draw draw, std::vector<HistoryPipeline> pipelines);
    // The measurement draw, after the pass's own graph pass, when counting.
    void add_measure(graph::RenderGraph& graph, const FrameInputs& in, const FrameResources& res,
                     RasterizedCount::Selection selection);
    void rebuild_pipelines(vk::DestroyList& retired) { rasterized_.rebuild_pipelines(retired); }

    // After the fence: the pass's counts, pipelines and samples passed into its own result;
    // its history (judged by `rules`) into the frame's. False when the pass did not run.
    bool collect(const FrameCollect& c, std::span<PassResult> own, FrameResult& frame,
                 const HistoryRules& rules);

  private:
    PassServices services_;
    VkDescriptorSetLayout set2_;
    vk::DescriptorSetLayout count_layout_;
    FrameDescriptorPool count_sets_;
    RasterizedCount rasterized_;
    DrawQueries queries_;
    PixelHistoryReplay history_;
    // This frame's.
    CountImages counts_;
    PipelineUses uses_;
    std::vector<HistoryPipeline> history_pipelines_;
};

}  // namespace ds::passes
