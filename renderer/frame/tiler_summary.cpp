#include "renderer/frame/tiler_summary.h"

#include <memory>

namespace ds {

std::optional<graph::TilerReport> tiler_summary(const graph::RenderGraph& graph) {
    const auto groups = graph.subpass_groups();
    if (groups.empty()) return std::nullopt;
    const graph::GroupPlan& g = groups.front();  // the frame has one (kSubpassGroup)
    const auto lazy = std::make_unique<bool[]>(g.attachments.size());
    for (size_t i = 0; i < g.attachments.size(); ++i)
        lazy[i] =
            graph.resources()[g.attachments[i].resource].lifetime == graph::Lifetime::Transient &&
            graph.lazily_allocated({g.attachments[i].resource});
    return graph::tiler_report(g, graph.resources(), {lazy.get(), g.attachments.size()});
}

}  // namespace ds
