#pragma once
// Where frames begin and end, and what --list shows of each. An application with a swapchain
// is delimited by vkQueuePresentKHR (frame N: the submissions after present N-1 up to present
// N, counted from 1); one without is delimited by its submissions that record a render pass or
// dynamic rendering with a depth attachment (frame N: the Nth such vkQueueSubmit).
#include <cstdint>
#include <cstdio>
#include <mutex>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace ds::layer {

// One render pass subpass or dynamic rendering, as --list prints it.
struct PassSummary {
    bool dynamic = false;  // dynamic rendering
    uint32_t subpass = 0;
    std::string label;     // the innermost debug-utils label open when it began
    uint32_t width = 0, height = 0;  // the render area's extent
    uint32_t x = 0, y = 0;           // and offset
    uint32_t view_mask = 0;
    VkFormat depth_format = VK_FORMAT_UNDEFINED;  // UNDEFINED: no depth attachment
    VkImage depth_image = VK_NULL_HANDLE;         // its image, where the layer knows it
    uint32_t samples = 1;
    uint32_t draws = 0;
};

class FrameTracker {
  public:
    // Opens the list file (list mode) in `out`. False with `error` when it cannot.
    bool open_list(const std::string& out, std::string& error);
    // A vkQueueSubmit's passes; `presenting`: the device has a swapchain. Returns the frame
    // number this submission belongs to.
    uint64_t submitted(const std::vector<PassSummary>& passes, bool presenting);
    void presented();
    // The device goes away: an unfinished frame is written as such.
    void finish();

    uint64_t frame() const { return frame_; }
    uint64_t depth_submissions() const { return depth_submissions_; }

  private:
    void write(bool presented);

    std::mutex mutex_;
    std::FILE* list_ = nullptr;
    uint64_t frame_ = 1;              // present-delimited frame under way
    uint64_t depth_submissions_ = 0;  // submissions with a depth pass so far
    bool presenting_ = false;
    std::vector<PassSummary> pending_;  // this frame's passes
    uint32_t pending_submissions_ = 0;
};

bool has_depth_pass(const std::vector<PassSummary>& passes);

}  // namespace ds::layer
