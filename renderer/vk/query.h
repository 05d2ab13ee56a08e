#pragma once
// Timestamp and occlusion queries: a pool of N slots reset per frame; results read without
// waiting (the caller has already waited on the frame's fence).
#include <cstdint>
#include <optional>
#include <vector>

#include <vulkan/vulkan.h>

namespace ds::vk {

class Context;

class TimestampPool {
  public:
    TimestampPool() = default;
    TimestampPool(Context& context, uint32_t count);  // count slots; throws if unsupported
    ~TimestampPool() { reset_handle(); }
    TimestampPool(TimestampPool&& other) noexcept { *this = std::move(other); }
    TimestampPool& operator=(TimestampPool&& other) noexcept;
    TimestampPool(const TimestampPool&) = delete;
    TimestampPool& operator=(const TimestampPool&) = delete;

    void reset(VkCommandBuffer cmd);  // must precede write() in the same frame
    void write(VkCommandBuffer cmd, VkPipelineStageFlags2 stage, uint32_t slot);
    // Raw ticks (masked to the valid bits) of every slot, or nullopt when not all are ready.
    std::optional<std::vector<uint64_t>> results() const;
    // Milliseconds between two ticks, wrap-around safe within the valid bits.
    double ticks_to_ms(uint64_t begin, uint64_t end) const;
    uint32_t count() const { return count_; }

  private:
    void reset_handle();

    VkDevice device_ = VK_NULL_HANDLE;
    VkQueryPool pool_ = VK_NULL_HANDLE;
    uint32_t count_ = 0;
    double period_ns_ = 1.0;
    uint64_t mask_ = ~0ull;
};

// Occlusion queries, begun with VK_QUERY_CONTROL_PRECISE_BIT (the device needs
// occlusionQueryPrecise): the exact number of samples that passed the depth test per query.
class OcclusionPool {
  public:
    OcclusionPool() = default;
    OcclusionPool(Context& context, uint32_t count);
    ~OcclusionPool() { reset_handle(); }
    OcclusionPool(OcclusionPool&& other) noexcept { *this = std::move(other); }
    OcclusionPool& operator=(OcclusionPool&& other) noexcept;
    OcclusionPool(const OcclusionPool&) = delete;
    OcclusionPool& operator=(const OcclusionPool&) = delete;

    void reset(VkCommandBuffer cmd, uint32_t count);  // outside a rendering, before begin()
    void begin(VkCommandBuffer cmd, uint32_t slot);
    void end(VkCommandBuffer cmd, uint32_t slot);
    // Samples passed per slot of the first `count`; nullopt when one is not available.
    std::optional<std::vector<uint64_t>> results(uint32_t count) const;
    uint32_t count() const { return count_; }

  private:
    void reset_handle();

    VkDevice device_ = VK_NULL_HANDLE;
    VkQueryPool pool_ = VK_NULL_HANDLE;
    uint32_t count_ = 0;
};

}  // namespace ds::vk
