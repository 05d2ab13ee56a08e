#include "renderer/passes/ao_temporal.h"

#include "renderer/passes/pass_util.h"

namespace ds::passes {

using graph::Access;

AoTemporalPass::AoTemporalPass(const PassServices& services)
    : accumulate_(services, kShader,
                  {KernelBinding::Sampled, KernelBinding::Sampled, KernelBinding::Storage},
                  sizeof(Push)),
      upsample_(services, kShader,
                {KernelBinding::Sampled, KernelBinding::Sampled, KernelBinding::Sampled,
                 KernelBinding::Storage},
                sizeof(Push)) {
    vk::DestroyList nothing_in_flight;
    rebuild_pipelines(nothing_in_flight);
}

void AoTemporalPass::rebuild_pipelines(vk::DestroyList& retired) {
    // Compile both before replacing either, so a failure leaves a matching pair.
    ComputeKernel::Prepared a = accumulate_.prepare({{"UPSAMPLE", "0"}});
    ComputeKernel::Prepared u = upsample_.prepare({{"UPSAMPLE", "1"}});
    accumulate_.install(std::move(a), retired);
    upsample_.install(std::move(u), retired);
}

// It filters gtao's output: it runs when gtao does and says why not when gtao does not.
void AoTemporalPass::configure(const FrameSetup&, FrameOptions& o) {
    if (o.gtao_skipped) set_skipped(*o.gtao_skipped);
}

void AoTemporalPass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    if (!res.ao_filtered.valid()) return;
    struct Data {
        graph::ImageHandle depth, normals, current, out;
        graph::HistoryImage history;
    };
    const Data& data = graph.add_pass<Data>(
        {"ao_temporal", graph::PassKind::Compute},
        [&](graph::PassBuilder& b, Data& d) {
            const VkExtent2D ao = b.extent(res.ao_filtered);
            d.out = b.create_image("ao", {.format = kFormat,
                                          .size = graph::ImageSize::relative(1.0f),
                                          .semantic = graph::Semantic::AO});
            d.history = b.create_history(kHistoryName,
                                         {.format = kHistoryFormat,
                                          .size = graph::ImageSize::fixed(ao.width, ao.height),
                                          .semantic = graph::Semantic::AO});
            b.read(res.frame_uniforms, Access::UniformRead);
            d.current = b.read(res.ao_filtered, Access::Sampled);
            b.read(d.history.previous, Access::Sampled);
            b.write(d.history.current, Access::StorageWrite);
            b.read(d.history.current, Access::Sampled);
            d.depth = b.read(res.depth, Access::Sampled);
            d.normals = b.read(res.normals, Access::Sampled);
            b.write(d.out, Access::StorageWrite);
        },
        [this, frame_set = in.frame_set, frame = in.frame_number](graph::PassContext& ctx,
                                                                  const Data& d) {
            last_history_valid_ = ctx.history_valid(d.history);
            const Push push{last_history_valid_ ? 1u : 0u, params_.history_weight,
                            params_.depth_tolerance, params_.plane_tolerance};
            const BoundImage history{ctx.view(d.history.current),
                                     ctx.layout(d.history.current)};  // GENERAL: both uses
            const BoundImage first[] = {
                {ctx.view(d.current), ctx.layout(d.current)},
                {ctx.view(d.history.previous), ctx.layout(d.history.previous)},
                history};
            accumulate_.dispatch(ctx.cmd(), frame_set, frame, first, &push,
                                 ctx.extent(d.history.current));
            // The upsample reads what the accumulation wrote.
            ctx.dependency(d.history.current, Access::StorageWrite, Access::Sampled);
            const BoundImage second[] = {{ctx.view(d.depth), ctx.layout(d.depth)},
                                         {ctx.view(d.normals), ctx.layout(d.normals)},
                                         history,
                                         {ctx.view(d.out), ctx.layout(d.out)}};
            upsample_.dispatch(ctx.cmd(), frame_set, frame, second, &push, ctx.extent(d.out));
        });
    res.ao = data.out;
}

}  // namespace ds::passes
