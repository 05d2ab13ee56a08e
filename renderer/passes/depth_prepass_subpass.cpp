// DepthPrepass in render_path=subpass (seed 002's subpass 0), and the pipelines of a frame.
#include "renderer/passes/depth_prepass.h"

namespace ds::passes {

using graph::Access;

DepthPrepass::Draw DepthPrepass::make_draw(const Variant& opaque, const Variant& tested,
                                           bool split) {
    Draw draw;
    if (split) {
        draw.opaque = pipelines_.get(opaque);
        draw.opaque_info = pipelines_.info(opaque);
        draw.mask = pipelines_.get(tested);
        draw.mask_info = pipelines_.info(tested);
    } else {
        draw.opaque = pipelines_.get(tested);
        draw.opaque_info = pipelines_.info(tested);
    }
    return draw;
}

DepthPrepass::Msaa DepthPrepass::declare_subpass(graph::PassBuilder& b, const FrameInputs& in,
                                                 FrameResources& res) const {
    b.subpass(kSubpassGroup, 0);
    const graph::ImageSize full = graph::ImageSize::relative(1.0f);
    const VkSampleCountFlagBits samples = in.options.samples;
    const bool msaa = in.options.msaa();
    VkClearValue clear{};
    // Attachment 0, the light (seed 002): what forward lights into in subpass 1. At 1x this
    // pass creates res.hdr (forward does on the dynamic path).
    if (!msaa)
        res.hdr = b.create_image(
            "hdr", {.format = kHdrFormat, .size = full, .semantic = graph::Semantic::HdrColor});
    const graph::ImageHandle light = msaa ? res.msaa_hdr : res.hdr;
    b.write(light, Access::ColorAttachment);
    for (size_t i = 0; i < 4; ++i) clear.color.float32[i] = kHdrBackground[i];
    b.clear(light, clear);
    Msaa out;
    if (in.options.gbuffer) {
        // Never resolved: at msaa > 1 forward reads each sample; at 1x they are the same.
        res.normals = b.create_image(msaa ? "msaa_normals" : "normals",
                                     {.format = kNormalFormat,
                                      .size = full,
                                      .samples = samples,
                                      .semantic = graph::Semantic::EncodedNormal});
        res.roughness = b.create_image(msaa ? "msaa_roughness" : "roughness",
                                       {.format = kRoughnessFormat,
                                        .size = full,
                                        .samples = samples,
                                        .semantic = graph::Semantic::UnormScalar});
        if (msaa) out = {res.normals, res.roughness, {}};
        const VkClearValue no_normal{.color = {{0.5f, 0.5f, 0.5f, 0.0f}}};  // the zero vector
        b.write(res.normals, Access::ColorAttachment);
        b.clear(res.normals, no_normal);
        b.write(res.roughness, Access::ColorAttachment);
        b.clear(res.roughness, VkClearValue{});
    }
    const graph::ImageHandle depth = msaa ? res.msaa_depth : res.depth;
    b.write(depth, Access::DepthAttachment);
    b.clear(depth, VkClearValue{.depthStencil = {in.options.far_depth(), 0}});
    b.read(res.frame_uniforms, Access::UniformRead,
           graph::Shader::Vertex | graph::Shader::Fragment);
    return out;
}

}  // namespace ds::passes
