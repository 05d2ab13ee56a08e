#include "renderer/passes/normals_from_depth.h"

namespace ds::passes {

using graph::Access;

NormalsFromDepthPass::NormalsFromDepthPass(const PassServices& services)
    : kernel_(services, kShader, {KernelBinding::Sampled, KernelBinding::Storage},
              /*push_constant_size=*/0) {
    vk::DestroyList nothing_in_flight;
    rebuild_pipelines(nothing_in_flight);
}

void NormalsFromDepthPass::rebuild_pipelines(vk::DestroyList& retired) {
    kernel_.rebuild(retired);
}

bool NormalsFromDepthPass::runs(const FrameOptions& o) {
    // gtao and contact_shadows are already false without the prepass (GtaoPass and
    // ContactShadowsPass::configure).
    return o.depth_only_prepass() && (o.gtao || o.contact_shadows);
}

void NormalsFromDepthPass::add(graph::RenderGraph& graph, const FrameInputs& in,
                               FrameResources& res) {
    if (!runs(in.options)) return;
    struct Data {
        graph::ImageHandle depth, normals;
    };
    const Data& data = graph.add_pass<Data>(
        {kName, graph::PassKind::Compute},
        [&](graph::PassBuilder& b, Data& d) {
            d.normals = b.create_image(kImage, {.format = kFormat,
                                                .size = graph::ImageSize::relative(1.0f),
                                                .semantic = graph::Semantic::EncodedNormal});
            b.read(res.frame_uniforms, Access::UniformRead);
            d.depth = b.read(res.depth, Access::Sampled);
            b.write(d.normals, Access::StorageWrite);
        },
        [this, frame_set = in.frame_set, frame = in.frame_number](graph::PassContext& ctx,
                                                                  const Data& d) {
            const BoundImage images[] = {{ctx.view(d.depth), ctx.layout(d.depth)},
                                         {ctx.view(d.normals), ctx.layout(d.normals)}};
            kernel_.dispatch(ctx.cmd(), frame_set, frame, images, nullptr, ctx.extent(d.normals));
        });
    res.normals = data.normals;
}

}  // namespace ds::passes
