#include "renderer/passes/clear_counts.h"

#include <vector>

namespace ds::passes {

void ClearCountsPass::add(graph::RenderGraph& graph, const FrameInputs&, FrameResources& res) {
    std::vector<graph::ImageHandle> counts;
    for (graph::ImageHandle h : {res.prepass_counts, res.forward_counts, res.transparent_counts})
        if (h.valid()) counts.push_back(h);
    if (counts.empty()) return;
    graph.add_pass(
        name(),
        [&](graph::PassBuilder& b) {
            for (graph::ImageHandle h : counts) b.write(h, graph::Access::TransferDst);
            return [counts](graph::PassContext& ctx) {
                const VkClearColorValue zero{};
                const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
                for (graph::ImageHandle h : counts)
                    vkCmdClearColorImage(ctx.cmd(), ctx.image(h), ctx.layout(h), &zero, 1, &range);
            };
        },
        graph::PassKind::Transfer);
}

}  // namespace ds::passes
