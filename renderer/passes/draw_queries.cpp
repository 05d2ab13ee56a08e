#include "renderer/passes/draw_queries.h"

#include <algorithm>

#include "renderer/common/error.h"

namespace ds::passes {

void DrawQueries::begin_frame(bool on, uint32_t max_draws) {
    on_ = on;
    slot_groups_.clear();
    capacity_ = on ? max_draws : 0;
    if (on && max_draws > pool_.count())
        pool_ = vk::OcclusionPool(context_, std::max(max_draws, 2 * pool_.count()));
}

void DrawQueries::reset(VkCommandBuffer cmd) {
    if (on_) pool_.reset(cmd, capacity_);
}

void DrawQueries::begin(VkCommandBuffer cmd, uint32_t group) {
    if (slot_groups_.size() >= capacity_)
        throw Error("draw queries: more draws recorded than the pass announced");
    pool_.begin(cmd, uint32_t(slot_groups_.size()));
    slot_groups_.push_back(group);
}

void DrawQueries::end(VkCommandBuffer cmd) {
    pool_.end(cmd, uint32_t(slot_groups_.size() - 1));
}

std::vector<std::optional<uint64_t>> DrawQueries::per_group(size_t groups) const {
    if (!on_) return {};
    std::vector<std::optional<uint64_t>> out(groups);
    const auto samples = pool_.results(uint32_t(slot_groups_.size()));
    if (!samples) throw Error("draw queries: results not available after the frame's fence");
    for (size_t i = 0; i < slot_groups_.size(); ++i) {
        std::optional<uint64_t>& g = out.at(slot_groups_[i]);
        g = g.value_or(0) + (*samples)[i];
    }
    return out;
}

}  // namespace ds::passes
