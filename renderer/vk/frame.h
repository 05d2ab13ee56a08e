#pragma once
// Frames in flight: each slot owns a command pool, a command buffer, a fence and a destroy
// list. begin() waits the slot's previous fence, then frees what that frame retired.
#include <array>
#include <cstdint>

#include <vulkan/vulkan.h>

#include "renderer/vk/destroy_list.h"

namespace ds::vk {

class Context;

struct Frame {
    VkCommandPool pool = VK_NULL_HANDLE;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;
    DestroyList retired;  // objects this frame replaced; destroyed after its fence
    bool submitted = false;
    uint64_t number = 0;
};

// Binary semaphores around a submit (presentation: wait for the acquired image, signal the
// present); none by default.
struct SubmitSemaphores {
    VkSemaphore wait = VK_NULL_HANDLE;
    VkPipelineStageFlags2 wait_stages = VK_PIPELINE_STAGE_2_NONE;
    VkSemaphore signal = VK_NULL_HANDLE;
};

class FrameRing {
  public:
    static constexpr uint32_t kFramesInFlight = 2;

    explicit FrameRing(Context& context);
    ~FrameRing();  // waits for every submitted frame first
    FrameRing(const FrameRing&) = delete;
    FrameRing& operator=(const FrameRing&) = delete;

    Frame& begin();  // the next slot, recording (ONE_TIME_SUBMIT)
    // Ends recording, submits, signals the slot's fence.
    void submit(Frame& frame, const SubmitSemaphores& semaphores = {});
    void wait(Frame& frame);  // blocks until the frame's fence has signalled
    // Objects replaced while recording the current frame N (older frames may still read
    // them). They die at begin() of frame N + kFramesInFlight, after N's fence; every older
    // frame's fence was already waited by the begin() calls in between.
    DestroyList& retire_list() { return frames_[current_].retired; }
    uint64_t frame_count() const { return count_; }

  private:
    Context& context_;
    std::array<Frame, kFramesInFlight> frames_;
    uint32_t current_ = 0;
    uint64_t count_ = 0;
};

}  // namespace ds::vk
