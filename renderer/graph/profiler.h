#pragma once
// Per-pass GPU time and pipeline statistics (DESIGN decision 6): the graph brackets every
// pass with a timestamp pair and a statistics query, so no pass can forget. One set of query
// pools per frame in flight; results are read after that frame's fence.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/vk/query.h"

#include "renderer/vk/destroy_list.h"
#include "renderer/vk/frame.h"

namespace ds::vk {
class Context;
}

namespace ds::graph {

struct PassResult {
    std::string name;
    double gpu_ms = 0.0;  // 0 when the device has no timestamps
    // When the pass began, after the frame's first timestamp (its first pass's begin): pass 0
    // starts at 0. From the same ticks as gpu_ms; 0 when the device has no timestamps.
    double gpu_start_ms = 0.0;
    // Pipeline statistics; 0 when the device has none. Lavapipe counts fragment invocations
    // per rasterized 4x4 block before the depth test (DESIGN decision 2).
    uint64_t vertex_invocations = 0;
    uint64_t fragment_invocations = 0;
    uint64_t clipping_primitives = 0;
    uint64_t compute_invocations = 0;
};

// Each pass's start (after ticks[0]) and duration in ms from its two ticks (begin, end per
// pass). Only the low `valid_bits` of a tick count, and the differences are taken modulo them:
// a counter that wrapped between two timestamps still gives their distance.
struct PassTime {
    double start_ms = 0.0;
    double gpu_ms = 0.0;
};
std::vector<PassTime> pass_times(std::span<const uint64_t> ticks, uint32_t valid_bits,
                                 double period_ns);

class PassProfiler {
  public:
    explicit PassProfiler(vk::Context& context);

    bool has_timestamps() const { return timestamps_; }
    bool has_statistics() const { return statistics_; }

    // Makes room for the passes of `frame` (replaced pools go to `retired`) and resets their
    // queries in `cmd`, before any of them is written.
    void begin_frame(VkCommandBuffer cmd, uint64_t frame, std::vector<std::string> pass_names,
                     vk::DestroyList& retired);
    void begin_pass(VkCommandBuffer cmd, uint32_t pass);
    void end_pass(VkCommandBuffer cmd, uint32_t pass);
    // Throws ds::Error when `frame` was never begun, was overwritten by a later frame, or its
    // queries are not available (collect() must follow the frame's fence).
    std::vector<PassResult> collect(uint64_t frame) const;

  private:
    struct Slot {
        vk::QueryPool timestamps;  // 2 per pass: begin, end
        vk::QueryPool statistics;  // 1 per pass
        uint64_t frame = UINT64_MAX;
        std::vector<std::string> names;
    };

    vk::Context& context_;
    bool timestamps_ = false;
    bool statistics_ = false;
    double period_ns_ = 1.0;
    uint32_t valid_bits_ = 64;
    std::vector<Slot> slots_ = std::vector<Slot>(vk::FrameRing::kFramesInFlight);
    size_t current_ = 0;  // the slot begin_frame() chose
};

}  // namespace ds::graph
