#include "layer/submit.h"

#include <cstring>

#include "layer/capture.h"
#include "layer/capture_state.h"
#include "layer/state.h"
#include "layer/summary.h"

namespace ds::layer {

namespace {

std::vector<PassSummary> summarize_all(DeviceData& d, const std::vector<VkCommandBuffer>& cbs) {
    std::vector<PassSummary> out;
    for (VkCommandBuffer cb : cbs) {
        const CommandBufferState* s = d.state(cb);
        DS_LAYER_LOG("  command buffer %p: %s, %zu commands", static_cast<void*>(cb),
                     s ? "known" : "unknown", s ? s->commands.size() : size_t(0));
        if (!s) continue;
        auto passes = summarize(d, *s);
        out.insert(out.end(), passes.begin(), passes.end());
    }
    return out;
}

// Counts the submission into its frame; true when it is to be captured (the chosen frame, with
// a depth pass, on the device capturing it or on the first to submit one). Then the caller
// holds process().capture_mutex until the submission is captured (`lock`).
bool note_submission(DeviceData& d, const std::vector<VkCommandBuffer>& cbs,
                     std::unique_lock<std::mutex>& lock) {
    const Config& c = config();
    if (c.mode == Config::Mode::Passive) return false;
    Process& proc = process();
    const auto passes = summarize_all(d, cbs);
    const uint64_t frame = proc.frames.submitted(passes, proc.presenting);
    DS_LAYER_LOG("submission of %zu command buffers: %zu passes, depth %d, frame %llu", cbs.size(),
                 passes.size(), int(has_depth_pass(passes)), (unsigned long long)frame);
    if (c.mode != Config::Mode::Capture || frame != c.frame || !has_depth_pass(passes))
        return false;
    lock = std::unique_lock(proc.capture_mutex);
    if (proc.captured || (proc.capturing && proc.capturing != &d)) return false;
    proc.capturing = &d;
    if (d.capture_refused.empty()) return true;
    d.capture = new FrameCapture(d);
    d.capture->not_analysed.push_back(d.capture_refused);
    finish_locked(d);
    return false;
}

// A frame delimited by its submission ends with it.
void submission_done(DeviceData& d) {
    if (!process().presenting) finish_locked(d);
}

VKAPI_ATTR VkResult VKAPI_CALL QueueSubmit(VkQueue queue, uint32_t n, const VkSubmitInfo* submits,
                                           VkFence fence) {
    DeviceData& d = device_of(queue);
    std::vector<VkCommandBuffer> cbs;
    for (uint32_t i = 0; i < n; ++i)
        cbs.insert(cbs.end(), submits[i].pCommandBuffers,
                   submits[i].pCommandBuffers + submits[i].commandBufferCount);
    std::unique_lock<std::mutex> lock;
    if (!note_submission(d, cbs, lock)) return d.t.QueueSubmit(queue, n, submits, fence);
    const VkResult r = capture_submit(d, queue, n, submits, fence);
    submission_done(d);
    return r;
}

VKAPI_ATTR VkResult VKAPI_CALL QueueSubmit2(VkQueue queue, uint32_t n,
                                            const VkSubmitInfo2* submits, VkFence fence) {
    DeviceData& d = device_of(queue);
    std::vector<VkCommandBuffer> cbs;
    for (uint32_t i = 0; i < n; ++i)
        for (uint32_t k = 0; k < submits[i].commandBufferInfoCount; ++k)
            cbs.push_back(submits[i].pCommandBufferInfos[k].commandBuffer);
    std::unique_lock<std::mutex> lock;
    if (!note_submission(d, cbs, lock)) return d.t.QueueSubmit2(queue, n, submits, fence);
    const VkResult r = capture_submit2(d, queue, n, submits, fence);
    submission_done(d);
    return r;
}

VKAPI_ATTR VkResult VKAPI_CALL QueuePresentKHR(VkQueue queue, const VkPresentInfoKHR* info) {
    DeviceData& d = device_of(queue);
    const VkResult r = d.t.QueuePresentKHR(queue, info);
    if (config().mode == Config::Mode::Passive) return r;
    Process& proc = process();
    if (proc.frames.frame() == config().frame) {
        std::lock_guard lock(proc.capture_mutex);
        if (proc.capturing) finish_locked(*proc.capturing);
    }
    proc.frames.presented();
    return r;
}

}  // namespace

PFN_vkVoidFunction submit_function(const char* name) {
    if (std::strcmp(name, "vkQueueSubmit2KHR") == 0) name = "vkQueueSubmit2";
#define DS_X(fn) \
    if (std::strcmp(name, "vk" #fn) == 0) return reinterpret_cast<PFN_vkVoidFunction>(&fn);
    DS_X(QueueSubmit)
    DS_X(QueueSubmit2)
    DS_X(QueuePresentKHR)
#undef DS_X
    return nullptr;
}

}  // namespace ds::layer
