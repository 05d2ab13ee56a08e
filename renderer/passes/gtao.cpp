#include "renderer/passes/gtao.h"

#include <string>

#include "renderer/common/error.h"

namespace ds::passes {

using graph::Access;

GtaoPass::GtaoPass(const PassServices& services, float resolution_scale)
    : kernel_(services, kShader,
              {KernelBinding::Sampled, KernelBinding::Sampled, KernelBinding::Storage},
              sizeof(Params)),
      scale_(resolution_scale) {
    if (!(scale_ > 0.0f && scale_ <= 1.0f))
        throw Error("gtao: resolution scale " + std::to_string(scale_) + " is not in (0, 1]");
    vk::DestroyList nothing_in_flight;
    rebuild_pipelines(nothing_in_flight);
}

void GtaoPass::rebuild_pipelines(vk::DestroyList& retired) {
    kernel_.rebuild(retired,
                    {{"SLICES", std::to_string(kSlices)}, {"STEPS", std::to_string(kSteps)}});
}

void GtaoPass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    if (!in.options.gtao) return;
    struct Data {
        graph::ImageHandle depth, normals, out;
    };
    const Data& data = graph.add_pass<Data>(
        "gtao",
        [&](graph::PassBuilder& b, Data& d) {
            d.out = b.create_image("ao_raw", {.format = kFormat,
                                              .size = graph::ImageSize::relative(scale_),
                                              .semantic = graph::Semantic::AO});
            b.read(res.frame_uniforms, Access::UniformRead);
            d.depth = b.read(res.depth, Access::Sampled);
            d.normals = b.read(res.normals, Access::Sampled);
            b.write(d.out, Access::StorageWrite);
        },
        [this, frame_set = in.frame_set, frame = in.frame_number](graph::PassContext& ctx,
                                                                  const Data& d) {
            const BoundImage images[] = {{ctx.view(d.depth), ctx.layout(d.depth)},
                                         {ctx.view(d.normals), ctx.layout(d.normals)},
                                         {ctx.view(d.out), ctx.layout(d.out)}};
            kernel_.dispatch(ctx.cmd(), frame_set, frame, images, &params_, ctx.extent(d.out));
        },
        graph::PassKind::Compute);
    res.ao_raw = data.out;
}

}  // namespace ds::passes
