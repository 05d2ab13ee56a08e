#include "renderer/vk/query.h"

#include <utility>

#include "renderer/common/error.h"
#include "renderer/vk/check.h"
#include "renderer/vk/context.h"
#include "renderer/vk/functions.h"

namespace ds::vk {

QueryPool::QueryPool(VkDevice device, VkQueryType type, uint32_t count,
                     VkQueryPipelineStatisticFlags statistics)
    : device_(device), count_(count) {
    auto info = make<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
    info.queryType = type;
    info.queryCount = count;
    info.pipelineStatistics = statistics;
    check(vkCreateQueryPool(device, &info, nullptr, &pool_), "vkCreateQueryPool");
}

QueryPool& QueryPool::operator=(QueryPool&& other) noexcept {
    if (this == &other) return *this;
    reset_handle();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    pool_ = std::exchange(other.pool_, VK_NULL_HANDLE);
    count_ = std::exchange(other.count_, 0);
    return *this;
}

void QueryPool::reset_handle() {
    if (pool_) vkDestroyQueryPool(device_, pool_, nullptr);
    pool_ = VK_NULL_HANDLE;
}

std::vector<uint64_t> QueryPool::results(uint32_t queries, uint32_t values) const {
    if (queries == 0) return {};
    // Each query's values, then its availability.
    const uint32_t stride = values + 1;
    std::vector<uint64_t> raw(size_t(queries) * stride);
    const VkResult result = vkGetQueryPoolResults(
        device_, pool_, 0, queries, raw.size() * sizeof(uint64_t), raw.data(),
        stride * sizeof(uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WITH_AVAILABILITY_BIT);
    if (result == VK_NOT_READY) return {};
    check(result, "vkGetQueryPoolResults");
    std::vector<uint64_t> out;
    out.reserve(size_t(queries) * values);
    for (uint32_t q = 0; q < queries; ++q) {
        if (raw[size_t(q) * stride + values] == 0) return {};
        for (uint32_t v = 0; v < values; ++v) out.push_back(raw[size_t(q) * stride + v]);
    }
    return out;
}

TimestampPool::TimestampPool(Context& context, uint32_t count) {
    const DeviceReport& report = context.report();
    if (!report.timestamps || report.timestamp_valid_bits == 0)
        throw Error("timestamps are not supported on " + report.candidate.name);
    period_ns_ = report.timestamp_period_ns;
    mask_ = report.timestamp_valid_bits >= 64 ? ~0ull : (1ull << report.timestamp_valid_bits) - 1;
    pool_ = QueryPool(context.device(), VK_QUERY_TYPE_TIMESTAMP, count);
}

void TimestampPool::reset(VkCommandBuffer cmd) {
    vkCmdResetQueryPool(cmd, pool_.handle(), 0, pool_.count());
}

void TimestampPool::write(VkCommandBuffer cmd, VkPipelineStageFlags2 stage, uint32_t slot) {
    fn().cmd_write_timestamp2(cmd, stage, pool_.handle(), slot);
}

std::optional<std::vector<uint64_t>> TimestampPool::results() const {
    std::vector<uint64_t> ticks = pool_.results(pool_.count(), 1);
    if (ticks.size() != pool_.count()) return std::nullopt;
    for (uint64_t& t : ticks) t &= mask_;
    return ticks;
}

double TimestampPool::ticks_to_ms(uint64_t begin, uint64_t end) const {
    const uint64_t delta = (end - begin) & mask_;
    return double(delta) * period_ns_ * 1e-6;
}

OcclusionPool::OcclusionPool(Context& context, uint32_t count) {
    if (!context.report().occlusion_query_precise)
        throw Error("precise occlusion queries are not supported on " +
                    context.report().candidate.name);
    pool_ = QueryPool(context.device(), VK_QUERY_TYPE_OCCLUSION, count);
}

void OcclusionPool::reset(VkCommandBuffer cmd, uint32_t count) {
    if (count) vkCmdResetQueryPool(cmd, pool_.handle(), 0, count);
}

void OcclusionPool::begin(VkCommandBuffer cmd, uint32_t slot) {
    vkCmdBeginQuery(cmd, pool_.handle(), slot, VK_QUERY_CONTROL_PRECISE_BIT);
}

void OcclusionPool::end(VkCommandBuffer cmd, uint32_t slot) {
    vkCmdEndQuery(cmd, pool_.handle(), slot);
}

std::optional<std::vector<uint64_t>> OcclusionPool::results(uint32_t count) const {
    if (count == 0) return std::vector<uint64_t>{};
    std::vector<uint64_t> samples = pool_.results(count, 1);
    if (samples.size() != count) return std::nullopt;
    return samples;
}

}  // namespace ds::vk
