#include "renderer/passes/clear_counts.h"

#include <algorithm>
#include <utility>
#include <vector>

#include "renderer/common/error.h"
#include "renderer/gpu_scene/gpu_scene.h"
#include "renderer/passes/pass_util.h"
#include "renderer/readback/host_readback.h"
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
    : services_(services), quads_(services.context.report().fragment_quad_operations) {}

void ClearCountsPass::add_draw_counters(graph::RenderGraph& graph, const FrameInputs& in,
                                        FrameResources& res) const {
    const VkDeviceSize bytes = std::max<size_t>(in.scene->draw_groups().size(), 1) * 4;
    const std::pair<CountImages*, const char*> passes[] = {
        {&res.shadow_counts, "shadow_draw_counts"},
        {&res.prepass_counts, "prepass_draw_counts"},
        {&res.forward_counts, "forward_draw_counts"},
        {&res.decal_counts, "decal_draw_counts"},
        {&res.transparent_counts, "transparent_draw_counts"}};
    for (const auto& [counts, name] : passes)
        if (counts->valid())
            counts->draws = services_.readback.import_storage(graph, name, bytes, bytes);
}

std::vector<SettingDef> ClearCountsPass::knobs() {
    return {bool_knob(kKnob, "measurement", false,
                      "count, per pixel, the fragments each geometry pass (shadow, prepass, "
                      "forward, decals, transparent) rasterized, shaded and discarded, and its "
                      "quads (report: rasterized_fragments, shaded_fragments, "
                      "discarded_fragments, quad_overdraw)",
                      Invalidates::Pipelines)};
}

void ClearCountsPass::configure(const FrameSetup& setup, FrameOptions& o) {
    if (!knob_value(setup.settings, kKnob)) return;
    o.requests.counts = true;
    if (o.subpass) set_turned_off(kKnob.name);
}

void ClearCountsPass::resolve(FrameOptions& o) {
    o.count_fragments = o.requests.counts && !o.subpass;
    const vk::DeviceReport& report = services_.context.report();
    if (o.count_fragments && !report.fragment_stores_and_atomics)
        throw Error("count_fragments=on needs fragmentStoresAndAtomics, which " +
                    report.candidate.name + " does not offer");
}

void ClearCountsPass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    const FrameOptions& o = in.options;
    if (!o.count_fragments && !o.zfight) return;
    const VkExtent2D frame = graph.output_extent();
    struct Data {
        std::vector<graph::ImageHandle> counts;
    };
    graph.add_pass<Data>(
        {name(), graph::PassKind::Transfer, role()},
        [&](graph::PassBuilder& b, Data& d) {
            if (o.count_fragments) {  // the passes that run this frame
                const VkExtent2D shadow{kShadowMapSize, kShadowMapSize};
                if (o.shadows) {
                    res.shadow_counts = create_counts(b, "shadow", shadow, quads_);
                    res.shadow_counts.in_view = false;  // the sun's view: no waste to speak of
                }
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
            d.counts = std::move(counts);
        },
        [](graph::PassContext& ctx, const Data& d) {
            const VkClearColorValue zero{};
            const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
            for (graph::ImageHandle h : d.counts)
                vkCmdClearColorImage(ctx.cmd(), ctx.image(h), ctx.layout(h), &zero, 1, &range);
        });
    // After the images exist: each counting pass gets its per-draw buffer.
    if (o.count_draws) add_draw_counters(graph, in, res);
}

}  // namespace ds::passes
