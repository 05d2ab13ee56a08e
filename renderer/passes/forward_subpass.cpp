// ForwardPass in render_path=subpass (seed 002's subpass 1), and the pipelines of a frame.
#include "renderer/passes/forward.h"

#include "renderer/vk/context.h"

namespace ds::passes {

using graph::Access;

ForwardPass::Draw ForwardPass::make_draw(const Variant& opaque, const Variant& mask,
                                         bool with_mask) {
    Draw draw;
    draw.opaque = pipelines_.get(opaque);
    draw.opaque_info = pipelines_.info(opaque);
    if (with_mask) {
        draw.mask = pipelines_.get(mask);
        draw.mask_info = pipelines_.info(mask);
    }
    return draw;
}

void ForwardPass::declare_subpass(graph::PassBuilder& b, const FrameInputs& in, FrameResources& res,
                                  const LightingInputs& lighting) const {
    b.subpass(kSubpassGroup, 1);
    const FrameOptions& o = in.options;
    // The light the prepass cleared (attachment 0), lit here; res.hdr at 1x is the prepass's.
    b.write(o.msaa() ? res.msaa_hdr : res.hdr, Access::ColorAttachment);
    b.read(o.msaa() ? res.msaa_depth : res.depth, Access::DepthReadOnly);
    if (o.gbuffer) {
        b.read(res.normals, Access::InputAttachment);
        b.read(res.roughness, Access::InputAttachment);
    }
    LightingSet::declare(b, lighting);
    b.read(res.frame_uniforms, Access::UniformRead,
           graph::Shader::Vertex | graph::Shader::Fragment);
}

VkDescriptorSet ForwardPass::input_set(graph::PassContext& ctx, const FrameInputs& in,
                                       const FrameResources& res) {
    const VkDescriptorSet set = input_sets_.allocate(in.frame_number, input_layout_.handle());
    vk::DescriptorWriter writer;
    writer.input_attachment(0, ctx.view(res.normals), ctx.layout(res.normals));
    writer.input_attachment(1, ctx.view(res.roughness), ctx.layout(res.roughness));
    writer.update(services_.context.device(), set);
    return set;
}

}  // namespace ds::passes
