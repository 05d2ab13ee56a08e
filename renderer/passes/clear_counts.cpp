#include "renderer/passes/clear_counts.h"

#include <algorithm>
#include <utility>
#include <vector>

#include "renderer/gpu_scene/gpu_scene.h"
#include "renderer/readback/host_readback.h"

namespace ds::passes {

void ClearCountsPass::add_draw_counters(graph::RenderGraph& graph, const FrameInputs& in,
                                        FrameResources& res) const {
    const VkDeviceSize bytes = std::max<size_t>(in.scene->draw_groups().size(), 1) * 4;
    const std::pair<CountImages*, const char*> passes[] = {
        {&res.prepass_counts, "prepass_draw_counts"},
        {&res.forward_counts, "forward_draw_counts"},
        {&res.decal_counts, "decal_draw_counts"},
        {&res.transparent_counts, "transparent_draw_counts"}};
    for (const auto& [counts, name] : passes)
        if (counts->valid())
            counts->draws = services_.readback.import_storage(graph, name, bytes, bytes);
}

void ClearCountsPass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    if (in.options.count_draws) add_draw_counters(graph, in, res);
    std::vector<graph::ImageHandle> counts;
    for (const CountImages& c :
         {res.prepass_counts, res.forward_counts, res.decal_counts, res.transparent_counts})
        if (c.valid()) counts.insert(counts.end(), {c.shaded, c.discarded});
    if (counts.empty() && !in.options.zfight) return;
    graph.add_pass(
        name(),
        [&](graph::PassBuilder& b) {
            if (in.options.zfight) {  // the zfight pass's competitors per pixel
                res.zfight = b.create_image("zfight", {.format = VK_FORMAT_R32_UINT,
                                                       .size = graph::ImageSize::relative(1.0f),
                                                       .semantic = graph::Semantic::Count});
                counts.push_back(res.zfight);
            }
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
