// One draw of the captured frame: counted, or drawn as the application drew it and listed.
#include "layer/capture_record.h"

namespace ds::layer {

void CountingRecorder::draw(const Command& c) {
    const bool counted_pass = in_pass_ && pass_ >= 0 && size_t(pass_) < plan_.pass_counted.size() &&
                              plan_.pass_counted[pass_];
    if (!counted_pass) {
        use_pipeline(app_pipeline_);
        c.call(d_.t, out_);
        return;
    }
    CapturedDraw draw;
    draw.pass = uint32_t(pass_);
    draw.index_in_pass = draws_in_pass_++;
    draw.labels = labels_;
    draw.pipeline = app_pipeline_;
    draw.args = std::get<DrawArgs>(c.payload);
    draw.slot = uint32_t(draws_.size());
    const CountingPipeline& p = pipelines_.get(app_pipeline_);
    if (!p.why.empty())
        draw.not_analysed = p.why;
    else if (app_queries_ > 0)
        draw.not_analysed = "inside the application's own occlusion query";
    else if (draw.slot >= plan_.counted_draws)
        draw.not_analysed = "more draws than the submission's plan";
    if (draw.not_analysed.empty()) {
        counted_draw(c, p, draw);
    } else {
        use_pipeline(app_pipeline_);
        c.call(d_.t, out_);
    }
    draws_.push_back(std::move(draw));
}

void CountingRecorder::counted_draw(const Command& c, const CountingPipeline& p,
                                    CapturedDraw& draw) {
    depth_draw(p, draw);
    const VkPipeline counting = p.has_fragment ? p.counting : app_pipeline_;
    use_pipeline(counting);
    bind_counters(p.layout, draw);
    d_.t.CmdBeginQuery(out_, res_.queries(), draw.slot, VK_QUERY_CONTROL_PRECISE_BIT);
    c.call(d_.t, out_);
    d_.t.CmdEndQuery(out_, res_.queries(), draw.slot);
    draw.queried = true;
    // The same draw again, measuring what it rasterizes whatever the tests do.
    use_pipeline(p.measure);
    set_dynamic_depth(p, false);
    c.call(d_.t, out_);
    set_dynamic_depth(p, true);
    if (draw.equal_counted) equal_draw(c, p, draw);
    use_pipeline(counting);
    restore_sets(p.app_sets);
}

// The depth and stencil switches the application sets dynamically: off for the measurement
// draw, then the application's values again.
void CountingRecorder::set_dynamic_depth(const CountingPipeline& p, bool app_values) {
    const auto value = [&](DynamicDepthArgs::Which w) {
        return app_values ? dynamic_depth_[w] : VK_FALSE;
    };
    if (p.dynamic_depth_test) d_.t.CmdSetDepthTestEnable(out_, value(DynamicDepthArgs::DepthTest));
    if (p.dynamic_depth_write)
        d_.t.CmdSetDepthWriteEnable(out_, value(DynamicDepthArgs::DepthWrite));
    if (p.dynamic_stencil_test)
        d_.t.CmdSetStencilTestEnable(out_, value(DynamicDepthArgs::StencilTest));
    if (p.dynamic_depth_bounds)
        d_.t.CmdSetDepthBoundsTestEnable(out_, value(DynamicDepthArgs::DepthBoundsTest));
}

// The layer's bind at its slot disturbed the application's sets from `from` on (its extended
// layout has empty layouts there): they are bound again as the application bound them.
void CountingRecorder::restore_sets(uint32_t from) {
    for (uint32_t s = from; s < d_.counter_set && s < sets_.size(); ++s) {
        const BoundSet& b = sets_[s];
        if (!b.valid) continue;
        d_.t.CmdBindDescriptorSets(out_, VK_PIPELINE_BIND_POINT_GRAPHICS, b.layout, s, 1, &b.set,
                                   uint32_t(b.offsets.size()),
                                   b.offsets.empty() ? nullptr : b.offsets.data());
    }
}

}  // namespace ds::layer
