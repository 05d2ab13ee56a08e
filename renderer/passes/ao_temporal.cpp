#include "renderer/passes/ao_temporal.h"

#include "renderer/passes/pass_util.h"

namespace ds::passes {

using graph::Access;

AoTemporalPass::AoTemporalPass(const PassServices& services)
    : kernel_(services, kShader,
              {KernelBinding::Sampled, KernelBinding::Sampled, KernelBinding::Sampled,
               KernelBinding::Sampled, KernelBinding::Storage, KernelBinding::Storage},
              sizeof(Push)) {
    vk::DestroyList nothing_in_flight;
    rebuild_pipelines(nothing_in_flight);
}

void AoTemporalPass::rebuild_pipelines(vk::DestroyList& retired) {
    kernel_.rebuild(retired);
}

std::optional<std::string> AoTemporalPass::skipped(const FrameInputs& in) const {
    if (in.options.gtao) return std::nullopt;
    return off_or_without_prepass(in, "gtao");
}

void AoTemporalPass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    if (!res.ao_filtered.valid()) return;
    struct Data {
        graph::ImageHandle depth, normals, current, out;
        graph::HistoryImage history;
    };
    const Data& data = graph.add_pass<Data>(
        "ao_temporal",
        [&](graph::PassBuilder& b, Data& d) {
            d.out = b.create_image("ao", {.format = kFormat,
                                          .size = graph::ImageSize::relative(1.0f),
                                          .semantic = graph::Semantic::AO});
            d.history = b.create_history(kHistoryName, {.format = kHistoryFormat,
                                                        .size = graph::ImageSize::relative(1.0f),
                                                        .semantic = graph::Semantic::AO});
            b.read(res.frame_uniforms, Access::UniformRead);
            d.depth = b.read(res.depth, Access::Sampled);
            d.normals = b.read(res.normals, Access::Sampled);
            d.current = b.read(res.ao_filtered, Access::Sampled);
            b.read(d.history.previous, Access::Sampled);
            b.write(d.out, Access::StorageWrite);
            b.write(d.history.current, Access::StorageWrite);
        },
        [this, frame_set = in.frame_set, frame = in.frame_number](graph::PassContext& ctx,
                                                                  const Data& d) {
            last_history_valid_ = ctx.history_valid(d.history);
            const Push push{last_history_valid_ ? 1u : 0u, params_.history_weight,
                            params_.depth_tolerance, params_.plane_tolerance};
            const BoundImage images[] = {
                {ctx.view(d.depth), ctx.layout(d.depth)},
                {ctx.view(d.normals), ctx.layout(d.normals)},
                {ctx.view(d.current), ctx.layout(d.current)},
                {ctx.view(d.history.previous), ctx.layout(d.history.previous)},
                {ctx.view(d.out), ctx.layout(d.out)},
                {ctx.view(d.history.current), ctx.layout(d.history.current)}};
            kernel_.dispatch(ctx.cmd(), frame_set, frame, images, &push, ctx.extent(d.out));
        },
        graph::PassKind::Compute);
    res.ao = data.out;
}

}  // namespace ds::passes
