#include "layer/capture_record.h"

namespace ds::layer {

SubmissionPlan plan_submission(DeviceData& d, const std::vector<const CommandBufferState*>& cbs) {
    SubmissionPlan plan;
    for (const CommandBufferState* cb : cbs) {
        const auto passes = summarize(d, *cb);
        plan.passes.insert(plan.passes.end(), passes.begin(), passes.end());
    }
    for (const PassSummary& p : plan.passes) {
        const bool counted = p.depth_format != VK_FORMAT_UNDEFINED && p.view_mask == 0;
        plan.pass_counted.push_back(counted);
        if (counted) plan.counted_draws += p.draws;
    }
    return plan;
}

CountingRecorder::CountingRecorder(DeviceData& d, CountingPipelines& pipelines,
                                   CaptureResources& res, const SubmissionPlan& plan,
                                   std::vector<std::string> labels, Bases bases,
                                   std::vector<DepthWritingPass> earlier)
    : d_(d),
      pipelines_(pipelines),
      res_(res),
      plan_(plan),
      labels_(std::move(labels)),
      bases_(bases),
      depth_passes_(std::move(earlier)) {}

void CountingRecorder::record(const CommandBufferState& cb, VkCommandBuffer out) {
    out_ = out;
    // Queries are reset outside any render pass: all of this buffer's, before it starts.
    if (plan_.counted_draws > 0)
        d_.t.CmdResetQueryPool(out_, res_.queries(), 0, plan_.counted_draws);
    sets_ = {};
    app_pipeline_ = bound_pipeline_ = VK_NULL_HANDLE;
    index_.reset();
    vertex_.clear();
    cb_ = &cb;
    for (command_ = 0; command_ < cb.commands.size(); ++command_) step(cb.commands[command_]);
    // The counters are read on the host once the submission is done.
    auto barrier = VkMemoryBarrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER, nullptr,
                                   VK_ACCESS_SHADER_WRITE_BIT, VK_ACCESS_HOST_READ_BIT};
    d_.t.CmdPipelineBarrier(out_, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                            VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

void CountingRecorder::step(const Command& c) {
    switch (c.op) {
        case Op::BindPipeline: {
            const auto& a = std::get<BindPipelineArgs>(c.payload);
            if (a.bind_point == VK_PIPELINE_BIND_POINT_GRAPHICS) {
                app_pipeline_ = a.pipeline;
                use_pipeline(a.pipeline);
                return;
            }
            break;
        }
        case Op::BindSets: bind_sets(std::get<BindSetsArgs>(c.payload)); break;
        case Op::BeginRenderPass: begin_instance(false, false); break;
        case Op::NextSubpass: begin_pass(false); break;
        case Op::BeginRendering: {
            const auto& a = std::get<RenderingArgs>(c.payload);
            begin_instance(a.resuming, a.suspending);
            break;
        }
        case Op::EndRenderPass:
        case Op::EndRendering:
            in_pass_ = false;
            c.call(d_.t, out_);
            if (!suspending_) end_render_pass_instance();
            return;
        case Op::State: track_state(c); break;
        case Op::Draw: draw(c); return;
        case Op::BeginLabel: labels_.push_back(std::get<LabelArgs>(c.payload).name); break;
        case Op::EndLabel:
            if (!labels_.empty()) labels_.pop_back();
            break;
        case Op::Query: {
            const auto& q = std::get<QueryArgs>(c.payload);
            std::lock_guard lock(d_.mutex);
            auto it = d_.query_types.find(q.pool);
            if (it != d_.query_types.end() && it->second == VK_QUERY_TYPE_OCCLUSION)
                app_queries_ = q.begin ? app_queries_ + 1 : app_queries_ - (app_queries_ > 0);
            break;
        }
        case Op::DynamicDepth: {
            const auto& a = std::get<DynamicDepthArgs>(c.payload);
            dynamic_depth_[a.which] = a.value;
            break;
        }
        case Op::Execute:
            notes.push_back("secondary command buffers: their draws are not counted");
            bound_pipeline_ = VK_NULL_HANDLE;
            break;
        default: break;
    }
    c.call(d_.t, out_);
}

// A render pass instance (or a dynamic rendering, which may resume a suspended one).
void CountingRecorder::begin_instance(bool resuming, bool suspending) {
    begin_pass(resuming);
    if (!resuming) {
        instance_first_pass_ = pass_;
        instance_cb_ = cb_;
    }
    suspending_ = suspending;
}

void CountingRecorder::begin_pass(bool dynamic_resume) {
    in_pass_ = true;
    if (dynamic_resume) return;
    ++pass_;
    draws_in_pass_ = 0;
}

void CountingRecorder::use_pipeline(VkPipeline p) {
    if (p != bound_pipeline_) d_.t.CmdBindPipeline(out_, VK_PIPELINE_BIND_POINT_GRAPHICS, p);
    bound_pipeline_ = p;
}

bool CountingRecorder::compatible(VkPipelineLayout a, VkPipelineLayout b, uint32_t set) {
    if (a == b) return true;
    std::lock_guard lock(d_.mutex);
    auto ia = d_.layouts.find(a), ib = d_.layouts.find(b);
    if (ia == d_.layouts.end() || ib == d_.layouts.end()) return false;
    const LayoutRecipe &la = ia->second, &lb = ib->second;
    if (la.sets.size() <= set || lb.sets.size() <= set) return false;
    if (la.push_constants.size() != lb.push_constants.size()) return false;
    for (size_t i = 0; i < la.push_constants.size(); ++i)
        if (la.push_constants[i].stageFlags != lb.push_constants[i].stageFlags ||
            la.push_constants[i].offset != lb.push_constants[i].offset ||
            la.push_constants[i].size != lb.push_constants[i].size)
            return false;
    for (uint32_t i = 0; i <= set; ++i)
        if (la.sets[i] != lb.sets[i]) return false;
    return true;
}

// Vulkan's rule: binding sets [first, last] with layout L disturbs any other bound set that L
// is not compatible with.
void CountingRecorder::bind_sets(const BindSetsArgs& a) {
    if (a.bind_point != VK_PIPELINE_BIND_POINT_GRAPHICS) return;
    const uint32_t last = a.first_set + uint32_t(a.sets.size());
    std::vector<uint32_t> per_set(a.sets.size(), 0);  // dynamic offsets each set takes
    {
        std::lock_guard lock(d_.mutex);
        auto l = d_.layouts.find(a.layout);
        for (size_t i = 0; l != d_.layouts.end() && i < a.sets.size(); ++i)
            if (a.first_set + i < l->second.sets.size())
                per_set[i] = d_.dynamic_descriptors[l->second.sets[a.first_set + i]];
    }
    size_t offset = 0;
    for (uint32_t s = 0; s < sets_.size(); ++s) {
        BoundSet& b = sets_[s];
        if (s >= a.first_set && s < last) {
            const uint32_t n = per_set[s - a.first_set];
            b = {a.layout, a.sets[s - a.first_set], {}, true};
            for (uint32_t k = 0; k < n && offset < a.dynamic_offsets.size(); ++k)
                b.offsets.push_back(a.dynamic_offsets[offset++]);
        } else if (b.valid && !compatible(a.layout, b.layout, s)) {
            b.valid = false;
        }
    }
}

}  // namespace ds::layer
