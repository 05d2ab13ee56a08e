#include "layer/capture.h"

#include <chrono>

#include "layer/capture_depth.h"
#include "layer/capture_output.h"
#include "layer/capture_state.h"
#include "layer/typed.h"

namespace ds::layer {

namespace {

using Clock = std::chrono::steady_clock;
// The depth records a submission holds, on average per pixel of its depth passes (the winner
// and one competitor), and at most.
constexpr uint64_t kRecordsPerPixel = 2;
constexpr uint64_t kMaxRecords = uint64_t(1) << 26;

FrameCapture& frame_capture(DeviceData& d) {
    if (!d.capture) d.capture = new FrameCapture(d);
    return *d.capture;
}

VkCommandPool pool_for(DeviceData& d, FrameCapture& fc, VkQueue queue) {
    uint32_t family = 0;
    {
        std::lock_guard lock(d.mutex);
        family = d.queue_families[queue];
    }
    VkCommandPool& pool = fc.pools[family];
    if (!pool) {
        auto info = typed<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
        info.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
        info.queueFamilyIndex = family;
        d.t.CreateCommandPool(d.device, &info, nullptr, &pool);
    }
    return pool;
}

// One submission's command buffers: the layer's counting copies where it can record them.
class Replacement {
  public:
    Replacement(DeviceData& d, VkQueue queue, const std::vector<VkCommandBuffer>& app)
        : d_(d), fc_(frame_capture(d)), app_(app) {
        pool_ = pool_for(d, fc_, queue);
        std::vector<const CommandBufferState*> states;
        for (VkCommandBuffer cb : app) {
            const CommandBufferState* s = d.state(cb);
            if (!s || s->level != VK_COMMAND_BUFFER_LEVEL_PRIMARY)
                fc_.not_analysed.push_back("a command buffer the layer did not see allocated");
            else if (!s->unrecordable.empty())
                fc_.not_analysed.push_back("a command buffer: " + s->unrecordable);
            else
                states.push_back(s);
            recordable_.push_back(states.size() && states.back() == s ? s : nullptr);
        }
        plan_ = plan_submission(d, states);
        std::vector<VkExtent2D> pixels, depth_pixels;
        uint64_t records = 0;
        const bool depth = config().settings.depth_records();
        for (size_t i = 0; i < plan_.passes.size(); ++i) {
            const PassSummary& p = plan_.passes[i];
            pixels.push_back(plan_.pass_counted[i] ? VkExtent2D{p.x + p.width, p.y + p.height}
                                                   : VkExtent2D{0, 0});
            depth_pixels.push_back(depth ? pixels.back() : VkExtent2D{0, 0});
            records += uint64_t(depth_pixels.back().width) * depth_pixels.back().height *
                       kRecordsPerPixel;
        }
        // The record buffer is one binding: at most maxStorageBufferRange (header, scratch).
        const uint64_t fits = (uint64_t(d.properties.limits.maxStorageBufferRange) - 32) / 16;
        res_ = std::make_unique<CaptureResources>(
            d, fc_.pipelines.set_layout(), plan_.counted_draws, pixels, depth_pixels,
            uint32_t(std::min({records, kMaxRecords, fits})));
        if (!res_->ok()) fc_.not_analysed.push_back("the frame's counters: " + res_->error());
    }

    ~Replacement() {
        if (!recorded_.empty())
            d_.t.FreeCommandBuffers(d_.device, pool_, uint32_t(recorded_.size()), recorded_.data());
    }

    // The handles to submit, in the application's order.
    std::vector<VkCommandBuffer> record();
    void read_back(uint32_t pass_base);
    const SubmissionPlan& plan() const { return plan_; }

  private:
    DeviceData& d_;
    FrameCapture& fc_;
    std::vector<VkCommandBuffer> app_;
    std::vector<const CommandBufferState*> recordable_;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    SubmissionPlan plan_;
    std::unique_ptr<CaptureResources> res_;
    std::unique_ptr<CountingRecorder> recorder_;
    std::vector<VkCommandBuffer> recorded_;
};

std::vector<VkCommandBuffer> Replacement::record() {
    if (!res_->ok()) return app_;
    recorder_ = std::make_unique<CountingRecorder>(
        d_, fc_.pipelines, *res_, plan_, fc_.labels,
        CountingRecorder::Bases{uint32_t(fc_.passes.size()), uint32_t(fc_.draws.size())},
        fc_.depth_passes);
    std::vector<VkCommandBuffer> out;
    for (size_t i = 0; i < app_.size(); ++i) {
        if (!recordable_[i]) {
            out.push_back(app_[i]);
            continue;
        }
        auto alloc = typed<VkCommandBufferAllocateInfo>(
            VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
        alloc.commandPool = pool_;
        alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        alloc.commandBufferCount = 1;
        VkCommandBuffer cb = VK_NULL_HANDLE;
        if (d_.t.AllocateCommandBuffers(d_.device, &alloc, &cb) != VK_SUCCESS) return app_;
        if (d_.set_loader_data) d_.set_loader_data(d_.device, cb);
        recorded_.push_back(cb);
        auto begin = typed<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
        begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        d_.t.BeginCommandBuffer(cb, &begin);
        recorder_->record(*recordable_[i], cb);
        d_.t.EndCommandBuffer(cb);
        out.push_back(cb);
    }
    recorder_->prepare(config().settings.zfight_steps);
    return out;
}

void Replacement::read_back(uint32_t pass_base) {
    if (!recorder_) return;
    const CountingRecorder::Bases bases{pass_base, uint32_t(fc_.draws.size())};
    for (const std::string& n : recorder_->notes) fc_.not_analysed.push_back(n);
    for (size_t i = 0; i < plan_.passes.size(); ++i) {
        CapturedPass p{plan_.passes[i], plan_.pass_counted[i], fc_.submissions, {}, 0, 0, {}, {}};
        if (p.summary.view_mask != 0 && p.summary.depth_format != VK_FORMAT_UNDEFINED)
            fc_.not_analysed.push_back("pass " + std::to_string(fc_.passes.size()) +
                                       ": multiview; its draws are not counted");
        if (p.counted) {
            p.pixel_width = p.summary.x + p.summary.width;
            p.pixel_height = p.summary.y + p.summary.height;
            const uint32_t* px = res_->pixels(uint32_t(i));
            p.pixels.assign(px, px + size_t(p.pixel_width) * p.pixel_height * 4);
        }
        fc_.passes.push_back(std::move(p));
    }
    for (CapturedDraw& draw : recorder_->draws()) {
        CapturedDrawResult r{draw, {}, 0};
        r.draw.pass += pass_base;
        if (draw.queried) {
            r.counts = res_->draw(draw.slot);
            d_.t.GetQueryPoolResults(d_.device, res_->queries(), draw.slot, 1, sizeof(uint64_t),
                                     &r.samples_passed, sizeof(uint64_t),
                                     VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT);
        }
        fc_.draws.push_back(std::move(r));
    }
    read_depth_records(fc_, *res_, *recorder_, plan_, bases);
    if (res_->bytes() > fc_.counter_bytes) {
        fc_.counter_bytes = res_->bytes();
        fc_.depth_record_bytes = config().settings.depth_records() ? res_->depth_record_bytes() : 0;
    }
}

template <typename Submit>
VkResult replace_and_submit(DeviceData& d, VkQueue queue, const std::vector<VkCommandBuffer>& app,
                            Submit submit) {
    const auto start = Clock::now();
    FrameCapture& fc = frame_capture(d);
    const uint32_t pass_base = uint32_t(fc.passes.size());
    VkResult r = VK_SUCCESS;
    {
        Replacement replacement(d, queue, app);
        const std::vector<VkCommandBuffer> cbs = replacement.record();
        r = submit(cbs);
        if (r == VK_SUCCESS) d.t.QueueWaitIdle(queue);
        if (r == VK_SUCCESS) replacement.read_back(pass_base);
    }
    ++fc.submissions;
    fc.capture_ms += std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    return r;
}

}  // namespace

VkResult capture_submit(DeviceData& d, VkQueue queue, uint32_t n, const VkSubmitInfo* submits,
                        VkFence fence) {
    std::vector<VkCommandBuffer> app;
    for (uint32_t i = 0; i < n; ++i)
        app.insert(app.end(), submits[i].pCommandBuffers,
                   submits[i].pCommandBuffers + submits[i].commandBufferCount);
    return replace_and_submit(d, queue, app, [&](const std::vector<VkCommandBuffer>& cbs) {
        std::vector<VkSubmitInfo> copy(submits, submits + n);
        size_t at = 0;
        for (VkSubmitInfo& s : copy) {
            s.pCommandBuffers = cbs.data() + at;
            at += s.commandBufferCount;
        }
        return d.t.QueueSubmit(queue, n, copy.data(), fence);
    });
}

VkResult capture_submit2(DeviceData& d, VkQueue queue, uint32_t n, const VkSubmitInfo2* submits,
                         VkFence fence) {
    std::vector<VkCommandBuffer> app;
    for (uint32_t i = 0; i < n; ++i)
        for (uint32_t k = 0; k < submits[i].commandBufferInfoCount; ++k)
            app.push_back(submits[i].pCommandBufferInfos[k].commandBuffer);
    return replace_and_submit(d, queue, app, [&](const std::vector<VkCommandBuffer>& cbs) {
        std::vector<VkSubmitInfo2> copy(submits, submits + n);
        std::vector<std::vector<VkCommandBufferSubmitInfo>> infos;
        size_t at = 0;
        for (VkSubmitInfo2& s : copy) {
            infos.emplace_back(s.pCommandBufferInfos,
                               s.pCommandBufferInfos + s.commandBufferInfoCount);
            for (auto& info : infos.back()) info.commandBuffer = cbs[at++];
            s.pCommandBufferInfos = infos.back().data();
        }
        return d.t.QueueSubmit2(queue, n, copy.data(), fence);
    });
}

void finish_capture(DeviceData& d) {
    std::lock_guard lock(process().capture_mutex);
    finish_locked(d);
}

void finish_locked(DeviceData& d) {
    if (!d.capture) return;
    write_capture(d, *d.capture, config().out);
    for (auto& [family, pool] : d.capture->pools) d.t.DestroyCommandPool(d.device, pool, nullptr);
    delete d.capture;
    d.capture = nullptr;
    process().captured = true;
    process().capturing = nullptr;
}

}  // namespace ds::layer
