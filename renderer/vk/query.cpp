#include "renderer/vk/query.h"
#include "renderer/vk/functions.h"

#include <utility>

#include "renderer/common/error.h"
#include "renderer/vk/check.h"
#include "renderer/vk/context.h"

namespace ds::vk {

TimestampPool::TimestampPool(Context& context, uint32_t count)
    : device_(context.device()), count_(count) {
    const DeviceReport& report = context.report();
    if (!report.timestamps || report.timestamp_valid_bits == 0)
        throw Error("timestamps are not supported on " + report.candidate.name);
    period_ns_ = report.timestamp_period_ns;
    mask_ = report.timestamp_valid_bits >= 64 ? ~0ull : (1ull << report.timestamp_valid_bits) - 1;
    auto info = make<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = count;
    check(vkCreateQueryPool(device_, &info, nullptr, &pool_), "vkCreateQueryPool");
}

TimestampPool& TimestampPool::operator=(TimestampPool&& other) noexcept {
    if (this == &other) return *this;
    reset_handle();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    pool_ = std::exchange(other.pool_, VK_NULL_HANDLE);
    count_ = std::exchange(other.count_, 0);
    period_ns_ = other.period_ns_;
    mask_ = other.mask_;
    return *this;
}

void TimestampPool::reset_handle() {
    if (pool_) vkDestroyQueryPool(device_, pool_, nullptr);
    pool_ = VK_NULL_HANDLE;
}

void TimestampPool::reset(VkCommandBuffer cmd) {
    vkCmdResetQueryPool(cmd, pool_, 0, count_);
}

void TimestampPool::write(VkCommandBuffer cmd, VkPipelineStageFlags2 stage, uint32_t slot) {
    fn().cmd_write_timestamp2(cmd, stage, pool_, slot);
}

std::optional<std::vector<uint64_t>> TimestampPool::results() const {
    // Pairs of (value, availability) so a query that never ran cannot read as 0 ticks.
    std::vector<uint64_t> raw(size_t(count_) * 2);
    const VkResult result = vkGetQueryPoolResults(
        device_, pool_, 0, count_, raw.size() * sizeof(uint64_t), raw.data(), 2 * sizeof(uint64_t),
        VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WITH_AVAILABILITY_BIT);
    if (result == VK_NOT_READY) return std::nullopt;
    check(result, "vkGetQueryPoolResults");
    std::vector<uint64_t> ticks(count_);
    for (uint32_t i = 0; i < count_; ++i) {
        if (raw[2 * i + 1] == 0) return std::nullopt;
        ticks[i] = raw[2 * i] & mask_;
    }
    return ticks;
}

double TimestampPool::ticks_to_ms(uint64_t begin, uint64_t end) const {
    const uint64_t delta = (end - begin) & mask_;
    return double(delta) * period_ns_ * 1e-6;
}

OcclusionPool::OcclusionPool(Context& context, uint32_t count)
    : device_(context.device()), count_(count) {
    if (!context.report().occlusion_query_precise)
        throw Error("precise occlusion queries are not supported on " +
                    context.report().candidate.name);
    auto info = make<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
    info.queryType = VK_QUERY_TYPE_OCCLUSION;
    info.queryCount = count;
    check(vkCreateQueryPool(device_, &info, nullptr, &pool_), "vkCreateQueryPool");
}

OcclusionPool& OcclusionPool::operator=(OcclusionPool&& other) noexcept {
    if (this == &other) return *this;
    reset_handle();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    pool_ = std::exchange(other.pool_, VK_NULL_HANDLE);
    count_ = std::exchange(other.count_, 0);
    return *this;
}

void OcclusionPool::reset_handle() {
    if (pool_) vkDestroyQueryPool(device_, pool_, nullptr);
    pool_ = VK_NULL_HANDLE;
}

void OcclusionPool::reset(VkCommandBuffer cmd, uint32_t count) {
    if (count) vkCmdResetQueryPool(cmd, pool_, 0, count);
}

void OcclusionPool::begin(VkCommandBuffer cmd, uint32_t slot) {
    vkCmdBeginQuery(cmd, pool_, slot, VK_QUERY_CONTROL_PRECISE_BIT);
}

void OcclusionPool::end(VkCommandBuffer cmd, uint32_t slot) {
    vkCmdEndQuery(cmd, pool_, slot);
}

std::optional<std::vector<uint64_t>> OcclusionPool::results(uint32_t count) const {
    if (count == 0) return std::vector<uint64_t>{};
    std::vector<uint64_t> raw(size_t(count) * 2);
    const VkResult result = vkGetQueryPoolResults(
        device_, pool_, 0, count, raw.size() * sizeof(uint64_t), raw.data(), 2 * sizeof(uint64_t),
        VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WITH_AVAILABILITY_BIT);
    if (result == VK_NOT_READY) return std::nullopt;
    check(result, "vkGetQueryPoolResults");
    std::vector<uint64_t> samples(count);
    for (uint32_t i = 0; i < count; ++i) {
        if (raw[2 * i + 1] == 0) return std::nullopt;
        samples[i] = raw[2 * i];
    }
    return samples;
}

}  // namespace ds::vk
