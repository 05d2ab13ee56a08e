// The recorder's part of the Z-fight and EQUAL checks (zfight, equal_check; depth_records.h):
// each counted draw's depth use and geometry; the EQUAL re-draw inside the application's pass;
// after a render pass instance, its depth-writing draws drawn twice more in the layer's
// attachment-less pass (nearest depth, then the records near it), with the state commands the
// application recorded before each of them replayed.
#include "layer/capture_record.h"
#include "layer/typed.h"

namespace ds::layer {

void CountingRecorder::bind_counters(VkPipelineLayout layout, const CapturedDraw& draw) {
    const VkDescriptorSet set = res_.set();
    const uint32_t offsets[3] = {res_.draw_offset(draw.slot), res_.pass_offset(draw.pass),
                                 res_.depth_offset(draw.pass)};
    d_.t.CmdBindDescriptorSets(out_, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, d_.counter_set, 1,
                               &set, 3, offsets);
}

void CountingRecorder::track_state(const Command& c) {
    if (const auto* v = std::get_if<VertexBuffersArgs>(&c.payload)) {
        for (size_t i = 0; i < v->buffers.size(); ++i)
            vertex_[v->first + uint32_t(i)] = {v->buffers[i], v->offsets[i]};
    } else if (const auto* ib = std::get_if<IndexBufferArgs>(&c.payload)) {
        index_ = *ib;
    }
}

// The draw's depth use and geometry; a depth-writing draw joins its pass's records and the
// passes later EQUAL draws match; an EQUAL-like one is matched with the latest earlier pass
// that wrote its depth attachment.
void CountingRecorder::depth_draw(const CountingPipeline& p, CapturedDraw& draw) {
    using W = DynamicDepthArgs::Which;
    draw.depth.test = p.dynamic_depth_test ? dynamic_depth_[W::DepthTest] != 0 : p.depth_test;
    draw.depth.write = p.dynamic_depth_write ? dynamic_depth_[W::DepthWrite] != 0 : p.depth_write;
    draw.depth.op = p.dynamic_compare_op ? VkCompareOp(dynamic_depth_[W::CompareOp]) : p.compare_op;
    draw.geometry.args = draw.args;
    draw.geometry.indexed = draw.args.indexed();
    if (draw.geometry.indexed && index_) {
        draw.geometry.index_buffer = index_->buffer;
        draw.geometry.index_offset = index_->offset;
        draw.geometry.index_type = index_->type;
    }
    for (uint32_t b : p.vertex_bindings)
        if (auto it = vertex_.find(b); it != vertex_.end()) draw.geometry.vertex[b] = it->second;
    const LayerSettings& s = config().settings;
    const uint32_t frame_pass = bases_.pass + draw.pass;
    const VkImage image = plan_.passes[draw.pass].depth_image;
    if (draw.depth.writes()) {
        if (depth_passes_.empty() || depth_passes_.back().pass != frame_pass)
            depth_passes_.push_back({frame_pass, image, {}});
        depth_passes_.back().draws.push_back({bases_.draw + draw.slot, draw.geometry});
        if (s.depth_records() && instance_cb_ != cb_) {
            draw.depth_why = "its render pass instance began in another command buffer";
        } else if (s.depth_records() && p.depth_record) {
            draw.depth_recorded = true;
            depth_draws_[draw.pass].push_back({command_, draw.slot});
            pass_reverse_.try_emplace(draw.pass, draw.depth.reverse());
        } else if (s.depth_records()) {
            draw.depth_why = p.depth_record_why;
        }
    }
    if (!s.equal_check || !draw.depth.equal_like()) return;
    if (!p.equal || p.samples > 1) {
        // Survivors are counted per pixel: at msaa > 1 two surfaces sharing a pixel's samples
        // would read as a tie.
        draw.depth_why = p.equal ? "a multisampled pass (the EQUAL check counts per pixel)"
                                 : p.equal_why;
        return;
    }
    for (auto pass = depth_passes_.rbegin(); pass != depth_passes_.rend(); ++pass) {
        if (pass->pass >= frame_pass || image == VK_NULL_HANDLE || pass->image != image) continue;
        for (const auto& [index, geometry] : pass->draws)
            if (same_geometry(geometry, draw.geometry)) {
                equal_matches_[draw.pass].insert(index);
                draw.equal_prepass = int32_t(pass->pass);
            }
        break;
    }
    draw.equal_counted = draw.equal_prepass >= 0;
    if (!draw.equal_counted) draw.depth_why = "no earlier depth pass draws its geometry";
}

// The EQUAL re-draw: its survivors passed the application's depth test (early tests).
void CountingRecorder::equal_draw(const Command& c, const CountingPipeline& p,
                                  CapturedDraw& draw) {
    use_pipeline(p.equal);
    bind_counters(p.layout, draw);
    if (p.dynamic_depth_write) d_.t.CmdSetDepthWriteEnable(out_, VK_FALSE);
    c.call(d_.t, out_);
    if (p.dynamic_depth_write)
        d_.t.CmdSetDepthWriteEnable(out_, dynamic_depth_[DynamicDepthArgs::DepthWrite]);
}

void CountingRecorder::depth_barrier() {
    auto barrier = VkMemoryBarrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER, nullptr,
                                   VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT,
                                   VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT |
                                       VK_ACCESS_TRANSFER_WRITE_BIT};
    const VkPipelineStageFlags stages =
        VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT;
    d_.t.CmdPipelineBarrier(out_, stages, stages, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

// After the application's render pass instance: each of its passes with depth records, twice.
void CountingRecorder::end_render_pass_instance() {
    bool drew = false;
    for (int pass = instance_first_pass_; pass <= pass_; ++pass) {
        const auto draws = depth_draws_.find(uint32_t(pass));
        if (draws == depth_draws_.end()) continue;
        const bool reverse = pass_reverse_.at(uint32_t(pass));
        depth_phase(uint32_t(pass), reverse ? DepthMode::NearestMax : DepthMode::NearestMin);
        depth_phase(uint32_t(pass), DepthMode::Record);
        drew = true;
    }
    if (!drew) return;
    depth_barrier();
    // The application's pipeline and sets as they were.
    bound_pipeline_ = VK_NULL_HANDLE;
    if (app_pipeline_) use_pipeline(app_pipeline_);
    restore_sets(0);
}

// One re-draw of `pass`'s depth-writing draws in `mode`: the state commands of this command
// buffer up to here replayed, each draw with its depth record pipeline.
void CountingRecorder::depth_phase(uint32_t pass, DepthMode mode) {
    depth_barrier();
    const uint32_t m = uint32_t(mode);
    d_.t.CmdUpdateBuffer(out_, res_.depth_buffer(), res_.depth_offset(pass) + 12, 4, &m);
    depth_barrier();
    const PassSummary& s = plan_.passes[pass];
    const VkExtent2D extent{s.x + s.width, s.y + s.height};
    auto begin = typed<VkRenderPassBeginInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO);
    begin.renderPass = pipelines_.empty_pass();
    begin.framebuffer = pipelines_.framebuffer(extent);
    begin.renderArea = {{0, 0}, extent};
    d_.t.CmdBeginRenderPass(out_, &begin, VK_SUBPASS_CONTENTS_INLINE);
    const auto& draws = depth_draws_.at(pass);
    VkPipeline app = VK_NULL_HANDLE;
    size_t next = 0;
    for (size_t i = 0; i < cb_->commands.size() && next < draws.size(); ++i) {
        const Command& c = cb_->commands[i];
        if (c.op == Op::State || c.op == Op::BindSets || c.op == Op::DynamicDepth) c.call(d_.t, out_);
        if (c.op == Op::BindPipeline) {
            const auto& a = std::get<BindPipelineArgs>(c.payload);
            if (a.bind_point == VK_PIPELINE_BIND_POINT_GRAPHICS) app = a.pipeline;
        }
        if (c.op != Op::Draw || i != draws[next].first) continue;
        const CountingPipeline& p = pipelines_.get(app);
        d_.t.CmdBindPipeline(out_, VK_PIPELINE_BIND_POINT_GRAPHICS, p.depth_record);
        bind_counters(p.layout, draws_[draws[next].second]);
        c.call(d_.t, out_);
        ++next;
    }
    d_.t.CmdEndRenderPass(out_);
}

void CountingRecorder::prepare(uint32_t steps) {
    for (const CapturedDraw& d : draws_)
        if (d.queried) res_.set_draw_id(d.slot, d.slot);
    if (!config().settings.depth_records()) return;
    for (uint32_t pass = 0; pass < plan_.passes.size(); ++pass) {
        if (!plan_.pass_counted[pass]) continue;
        const auto reverse = pass_reverse_.find(pass);
        const bool max = reverse != pass_reverse_.end() && reverse->second;
        const uint32_t params = steps | depth_bits_of(plan_.passes[pass].depth_format) << 16;
        res_.init_depth_pass(pass, params,
                             max ? DepthMode::NearestMax : DepthMode::NearestMin);
    }
}

}  // namespace ds::layer
