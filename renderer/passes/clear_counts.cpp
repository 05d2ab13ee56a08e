#include "renderer/passes/clear_counts.h"

#include <vector>

#include "renderer/passes/pass_util.h"
#include "renderer/vk/capabilities.h"
#include "renderer/vk/context.h"

namespace ds::passes {
namespace {

// Creates one counting pass's images (named "<prefix>_counts", "_discarded", "_rasterized",
// "_quads") at `size`, the quads at half of it, rounded up.
CountImages create_counts(graph::PassBuilder& b, const char* prefix, VkExtent2D size, bool quads) {
    auto image = [&](const char* kind, VkExtent2D extent) {
        return b.create_image(std::string(prefix) + "_" + kind,
                              {.format = kCountFormat,
                               .size = graph::ImageSize::fixed(extent.width, extent.height),
                               .semantic = graph::Semantic::Count});
    };
    CountImages c;
    c.shaded = image("counts", size);
    c.discarded = image("discarded", size);
    c.rasterized = image("rasterized", size);
    if (quads) c.quads = image("quads", {(size.width + 1) / 2, (size.height + 1) / 2});
    return c;
}

}  // namespace

ClearCountsPass::ClearCountsPass(const PassServices& services)
    : quads_(services.context.report().fragment_quad_operations) {}

void ClearCountsPass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    const FrameOptions& o = in.options;
    if (!o.count_fragments && !o.zfight) return;
    const VkExtent2D frame = graph.output_extent();
    graph.add_pass(
        name(),
        [&](graph::PassBuilder& b) {
            if (o.count_fragments) {  // the passes that run this frame
                const VkExtent2D shadow{kShadowMapSize, kShadowMapSize};
                if (o.shadows) res.shadow_counts = create_counts(b, "shadow", shadow, quads_);
                if (o.prepass) res.prepass_counts = create_counts(b, "prepass", frame, quads_);
                res.forward_counts = create_counts(b, "forward", frame, quads_);
                if (o.decal_pass) res.decal_counts = create_counts(b, "decal", frame, quads_);
                res.transparent_counts = create_counts(b, "transparent", frame, quads_);
            }
            std::vector<graph::ImageHandle> counts = count_images(res);
            if (o.zfight) {  // the zfight pass's competitors per pixel
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
