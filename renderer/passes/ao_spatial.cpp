#include "renderer/passes/ao_spatial.h"

#include "renderer/passes/pass_util.h"

namespace ds::passes {

using graph::Access;

namespace {

ComputeKernel make_blur_kernel(const PassServices& services) {
    return ComputeKernel(services, AoSpatialPass::kShader,
                         {KernelBinding::Sampled, KernelBinding::Storage},
                         sizeof(AoSpatialPass::Params));
}

}  // namespace

AoSpatialPass::AoSpatialPass(const PassServices& services)
    : horizontal_(make_blur_kernel(services)), vertical_(make_blur_kernel(services)) {
    vk::DestroyList nothing_in_flight;
    rebuild_pipelines(nothing_in_flight);
}

void AoSpatialPass::rebuild_pipelines(vk::DestroyList& retired) {
    // Compile both before replacing either, so a failure leaves a matching pair.
    ComputeKernel::Prepared h = horizontal_.prepare({{"VERTICAL", "0"}});
    ComputeKernel::Prepared v = vertical_.prepare({{"VERTICAL", "1"}});
    horizontal_.install(std::move(h), retired);
    vertical_.install(std::move(v), retired);
}

// It filters gtao's output: it runs when gtao does and says why not when gtao does not.
void AoSpatialPass::configure(const FrameSetup&, FrameOptions& o) {
    if (o.gtao_skipped) set_skipped(*o.gtao_skipped);
}

void AoSpatialPass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    if (!res.ao_raw.valid()) return;
    struct Data {
        graph::ImageHandle raw, mid, out;
    };
    const Data& data = graph.add_pass<Data>(
        {"ao_spatial", graph::PassKind::Compute},
        [&](graph::PassBuilder& b, Data& d) {
            const VkExtent2D raw = b.extent(res.ao_raw);
            const graph::ImageSize size = graph::ImageSize::fixed(raw.width, raw.height);
            d.mid = b.create_image(
                kIntermediateName,
                {.format = kIntermediateFormat, .size = size, .semantic = graph::Semantic::AO});
            d.out = b.create_image(
                "ao_filtered", {.format = kFormat, .size = size, .semantic = graph::Semantic::AO});
            b.read(res.frame_uniforms, Access::UniformRead);
            d.raw = b.read(res.ao_raw, Access::Sampled);
            b.write(d.mid, Access::StorageWrite);
            b.read(d.mid, Access::Sampled);
            b.write(d.out, Access::StorageWrite);
        },
        [this, frame_set = in.frame_set, frame = in.frame_number](graph::PassContext& ctx,
                                                                  const Data& d) {
            const BoundImage mid{ctx.view(d.mid), ctx.layout(d.mid)};  // GENERAL: both uses
            const BoundImage first[] = {{ctx.view(d.raw), ctx.layout(d.raw)}, mid};
            horizontal_.dispatch(ctx.cmd(), frame_set, frame, first, &params_, ctx.extent(d.mid));
            // The graph orders passes; inside this one, the vertical dispatch reads what the
            // horizontal one wrote.
            ctx.dependency(d.mid, Access::StorageWrite, Access::Sampled);
            const BoundImage second[] = {mid, {ctx.view(d.out), ctx.layout(d.out)}};
            vertical_.dispatch(ctx.cmd(), frame_set, frame, second, &params_, ctx.extent(d.out));
        });
    res.ao_filtered = data.out;
}

}  // namespace ds::passes
