#include "renderer/passes/contact_shadows.h"

#include <string>

namespace ds::passes {

using graph::Access;

ContactShadowsPass::ContactShadowsPass(const PassServices& services)
    : kernel_(services, kShader,
              {KernelBinding::Sampled, KernelBinding::Sampled, KernelBinding::Storage},
              sizeof(Params)) {
    vk::DestroyList nothing_in_flight;
    rebuild_pipelines(nothing_in_flight);
}

void ContactShadowsPass::rebuild_pipelines(vk::DestroyList& retired) {
    kernel_.rebuild(retired, {{"STEPS", std::to_string(kSteps)}});
}

void ContactShadowsPass::add(graph::RenderGraph& graph, const FrameInputs& in,
                             FrameResources& res) {
    if (!in.options.contact_shadows) return;
    struct Data {
        graph::ImageHandle depth, normals, out;
    };
    const Data& data = graph.add_pass<Data>(
        "contact_shadows",
        [&](graph::PassBuilder& b, Data& d) {
            d.out = b.create_image("contact_shadows", {.format = kFormat,
                                                       .size = graph::ImageSize::relative(1.0f),
                                                       .semantic = graph::Semantic::UnormScalar});
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
    res.contact_shadows = data.out;
}

}  // namespace ds::passes
