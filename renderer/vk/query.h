#pragma once
// Queries: a pool of N slots reset per frame; results read without waiting (the caller has
// already waited on the frame's fence). QueryPool owns the VkQueryPool and reads any type's
// results; TimestampPool and OcclusionPool add what their query type needs.
#include <cstdint>
#include <optional>
#include <vector>

#include <vulkan/vulkan.h>

namespace ds::vk {

class Context;

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
    // them is not available (yet): each is read with its availability, so a query that never
    // ran cannot read as 0.
    std::vector<uint64_t> results(uint32_t queries, uint32_t values) const;

  private:
    void reset_handle();

    VkDevice device_ = VK_NULL_HANDLE;
    VkQueryPool pool_ = VK_NULL_HANDLE;
    uint32_t count_ = 0;
};

class TimestampPool {
  public:
    TimestampPool() = default;
    TimestampPool(Context& context, uint32_t count);  // count slots; throws if unsupported

    void reset(VkCommandBuffer cmd);  // must precede write() in the same frame
    void write(VkCommandBuffer cmd, VkPipelineStageFlags2 stage, uint32_t slot);
    // Raw ticks (masked to the valid bits) of every slot, or nullopt when not all are ready.
    std::optional<std::vector<uint64_t>> results() const;
    // Milliseconds between two ticks, wrap-around safe within the valid bits.
    double ticks_to_ms(uint64_t begin, uint64_t end) const;
    uint32_t count() const { return pool_.count(); }

  private:
    QueryPool pool_;
    double period_ns_ = 1.0;
    uint64_t mask_ = ~0ull;
};

// Occlusion queries, begun with VK_QUERY_CONTROL_PRECISE_BIT (the device needs
// occlusionQueryPrecise): the exact number of samples that passed the depth test per query.
class OcclusionPool {
  public:
    OcclusionPool() = default;
    OcclusionPool(Context& context, uint32_t count);

    void reset(VkCommandBuffer cmd, uint32_t count);  // outside a rendering, before begin()
    void begin(VkCommandBuffer cmd, uint32_t slot);
    void end(VkCommandBuffer cmd, uint32_t slot);
    // Samples passed per slot of the first `count`; nullopt when one is not available.
    std::optional<std::vector<uint64_t>> results(uint32_t count) const;
    uint32_t count() const { return pool_.count(); }

  private:
    QueryPool pool_;
};

}  // namespace ds::vk
