#pragma once
// Per-pass GPU time and pipeline statistics (DESIGN decision 6): the graph brackets every
// pass with a timestamp pair and a statistics query, so no pass can forget. One set of query
// pools per frame in flight; results are read after that frame's fence.
#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/vk/destroy_list.h"
#include "renderer/vk/frame.h"

namespace ds::vk {
class Context;
}

namespace ds::graph {

struct PassResult {
    std::string name;
    double gpu_ms = 0.0;  // 0 when the device has no timestamps
    // Pipeline statistics; 0 when the device has none. Lavapipe counts fragment invocations
    // per rasterized 4x4 block before the depth test (DESIGN decision 2).
    uint64_t vertex_invocations = 0;
    uint64_t fragment_invocations = 0;
    uint64_t clipping_primitives = 0;
    uint64_t compute_invocations = 0;
};

// A VkQueryPool, move-only (so a replaced one can wait in a DestroyList).
class QueryPool {
  public:
    QueryPool() = default;
    QueryPool(VkDevice device, VkQueryType type, uint32_t count,
              VkQueryPipelineStatisticFlags statistics = 0);
    ~QueryPool() { reset_handle(); }
    QueryPool(QueryPool&& other) noexcept { *this = std::move(other); }
    QueryPool& operator=(QueryPool&& other) noexcept;
    QueryPool(const QueryPool&) = delete;
    QueryPool& operator=(const QueryPool&) = delete;

    VkQueryPool handle() const { return pool_; }
    uint32_t count() const { return count_; }
    // `values` 64-bit values per query for the first `queries` queries, or empty when one of
    // them is not available (yet).
    std::vector<uint64_t> results(uint32_t queries, uint32_t values) const;

  private:
    void reset_handle();

    VkDevice device_ = VK_NULL_HANDLE;
    VkQueryPool pool_ = VK_NULL_HANDLE;
    uint32_t count_ = 0;
};

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
        QueryPool timestamps;  // 2 per pass: begin, end
        QueryPool statistics;  // 1 per pass
        uint64_t frame = UINT64_MAX;
        std::vector<std::string> names;
    };

    vk::Context& context_;
    bool timestamps_ = false;
    bool statistics_ = false;
    double period_ns_ = 1.0;
    uint64_t mask_ = ~0ull;
    std::vector<Slot> slots_ = std::vector<Slot>(vk::FrameRing::kFramesInFlight);
    size_t current_ = 0;  // the slot begin_frame() chose
};

}  // namespace ds::graph
