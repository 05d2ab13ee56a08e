#include "renderer/graph/profiler.h"

#include <utility>

#include "renderer/common/error.h"
#include "renderer/vk/check.h"
#include "renderer/vk/context.h"
#include "renderer/vk/functions.h"

namespace ds::graph {
namespace {

// Results come back in bit order: vertex, clipping, fragment, compute.
constexpr VkQueryPipelineStatisticFlags kStatistics =
    VK_QUERY_PIPELINE_STATISTIC_VERTEX_SHADER_INVOCATIONS_BIT |
    VK_QUERY_PIPELINE_STATISTIC_CLIPPING_PRIMITIVES_BIT |
    VK_QUERY_PIPELINE_STATISTIC_FRAGMENT_SHADER_INVOCATIONS_BIT |
    VK_QUERY_PIPELINE_STATISTIC_COMPUTE_SHADER_INVOCATIONS_BIT;
constexpr uint32_t kStatisticCount = 4;

}  // namespace

std::vector<PassTime> pass_times(std::span<const uint64_t> ticks, uint32_t valid_bits,
                                 double period_ns) {
    const uint64_t mask = valid_bits >= 64 ? ~0ull : (1ull << valid_bits) - 1;
    const auto ms = [&](uint64_t from, uint64_t to) {
        return double(((to & mask) - (from & mask)) & mask) * period_ns * 1e-6;
    };
    std::vector<PassTime> times(ticks.size() / 2);
    for (size_t i = 0; i < times.size(); ++i) {
        times[i].start_ms = ms(ticks[0], ticks[2 * i]);
        times[i].gpu_ms = ms(ticks[2 * i], ticks[2 * i + 1]);
    }
    return times;
}

PassProfiler::PassProfiler(vk::Context& context) : context_(context) {
    const vk::DeviceReport& report = context.report();
    timestamps_ = report.timestamps && report.timestamp_valid_bits > 0;
    statistics_ = report.pipeline_statistics;  // the context enables the feature when present
    period_ns_ = report.timestamp_period_ns;
    valid_bits_ = report.timestamp_valid_bits;
}

void PassProfiler::begin_frame(VkCommandBuffer cmd, uint64_t frame,
                               std::vector<std::string> pass_names, vk::DestroyList& retired) {
    current_ = size_t(frame % slots_.size());
    Slot& slot = slots_[current_];
    const uint32_t passes = uint32_t(pass_names.size());
    slot.frame = frame;
    slot.names = std::move(pass_names);
    if (passes == 0) return;
    const VkDevice device = context_.device();
    // Pools only grow; the slot's previous frame may still be in flight for all we know here.
    if (timestamps_ && slot.timestamps.count() < 2 * passes) {
        if (slot.timestamps.handle()) retired.defer(std::move(slot.timestamps));
        slot.timestamps = vk::QueryPool(device, VK_QUERY_TYPE_TIMESTAMP, 2 * passes);
    }
    if (statistics_ && slot.statistics.count() < passes) {
        if (slot.statistics.handle()) retired.defer(std::move(slot.statistics));
        slot.statistics =
            vk::QueryPool(device, VK_QUERY_TYPE_PIPELINE_STATISTICS, passes, kStatistics);
    }
    if (timestamps_) vkCmdResetQueryPool(cmd, slot.timestamps.handle(), 0, 2 * passes);
    if (statistics_) vkCmdResetQueryPool(cmd, slot.statistics.handle(), 0, passes);
}

// Top of pipe to all commands: the time from reaching the pass (after its barriers) until
// everything recorded so far has finished.
void PassProfiler::begin_pass(VkCommandBuffer cmd, uint32_t pass) {
    const Slot& slot = slots_[current_];
    if (timestamps_)
        vk::fn().cmd_write_timestamp2(cmd, VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT,
                                      slot.timestamps.handle(), 2 * pass);
    if (statistics_) vkCmdBeginQuery(cmd, slot.statistics.handle(), pass, 0);
}

void PassProfiler::end_pass(VkCommandBuffer cmd, uint32_t pass) {
    const Slot& slot = slots_[current_];
    if (statistics_) vkCmdEndQuery(cmd, slot.statistics.handle(), pass);
    if (timestamps_)
        vk::fn().cmd_write_timestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                                      slot.timestamps.handle(), 2 * pass + 1);
}

std::vector<PassResult> PassProfiler::collect(uint64_t frame) const {
    const Slot& slot = slots_[frame % slots_.size()];
    if (slot.frame != frame)
        throw Error("render graph: results of frame " + std::to_string(frame) +
                    (slot.frame == UINT64_MAX || slot.frame < frame ? " do not exist yet"
                                                                    : " were overwritten"));
    const uint32_t passes = uint32_t(slot.names.size());
    std::vector<PassResult> results(passes);
    for (uint32_t i = 0; i < passes; ++i) results[i].name = slot.names[i];
    if (passes == 0) return results;
    if (timestamps_) {
        const std::vector<uint64_t> ticks = slot.timestamps.results(2 * passes, 1);
        if (ticks.empty())
            throw Error("render graph: timestamps not ready (collect before fence?)");
        const std::vector<PassTime> times = pass_times(ticks, valid_bits_, period_ns_);
        for (uint32_t i = 0; i < passes; ++i) {
            results[i].gpu_start_ms = times[i].start_ms;
            results[i].gpu_ms = times[i].gpu_ms;
        }
    }
    if (statistics_) {
        const std::vector<uint64_t> stats = slot.statistics.results(passes, kStatisticCount);
        if (stats.empty())
            throw Error("render graph: statistics not ready (collect before fence?)");
        for (uint32_t i = 0; i < passes; ++i) {
            const uint64_t* s = &stats[size_t(i) * kStatisticCount];
            results[i].vertex_invocations = s[0];
            results[i].clipping_primitives = s[1];
            results[i].fragment_invocations = s[2];
            results[i].compute_invocations = s[3];
        }
    }
    return results;
}

}  // namespace ds::graph
