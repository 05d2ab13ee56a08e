#include "renderer/passes/skybox.h"

#include "renderer/shader/compiler.h"
#include "renderer/vk/context.h"
#include "renderer/vk/functions.h"

namespace ds::passes {

using graph::Access;

SkyboxPass::SkyboxPass(const PassServices& services)
    : services_(services),
      pipelines_([this](uint32_t key) { return compile(key); },
                 [this](uint32_t key, const ShaderStages& s) { return create(key, s); }) {
    const VkDescriptorSetLayout sets[] = {services.frame_layout};
    layout_ = vk::PipelineLayout(services.context, sets, {}, "skybox layout");
    pipelines_.get(0);
}

void SkyboxPass::rebuild_pipelines(vk::DestroyList& retired) {
    pipelines_.rebuild(retired);
}

ShaderStages SkyboxPass::compile(uint32_t) const {
    return {services_.compiler.compile("fullscreen.vert", shader::Stage::Vertex).spirv,
            services_.compiler.compile("skybox.frag", shader::Stage::Fragment).spirv};
}

vk::Pipeline SkyboxPass::create(uint32_t key, const ShaderStages& s) const {
    vk::GraphicsPipelineBuilder b;
    return b.shader(VK_SHADER_STAGE_VERTEX_BIT, s.vert)
        .shader(VK_SHADER_STAGE_FRAGMENT_BIT, s.frag)
        .color_attachment(VK_FORMAT_R16G16B16A16_SFLOAT)
        .depth_attachment(services_.depth_format)
        .samples(key_samples(key))
        .layout(layout_.handle())
        .build(services_.context, "skybox");
}

void SkyboxPass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    const VkPipeline pipeline = pipelines_.get(samples_key(in.options.samples));
    // msaa > 1: into the multisampled colour, against the multisampled depth, before
    // transparent resolves: a silhouette pixel's sky samples blend with its surface samples.
    const bool msaa = in.options.msaa();
    const graph::ImageHandle hdr = msaa ? res.msaa_hdr : res.hdr;
    const graph::ImageHandle depth_image = msaa ? res.msaa_depth : res.depth;
    struct Data {
        FrameInputs in;
        graph::ImageHandle hdr, depth;
    };
    graph.add_pass<Data>(
        kName,
        [&](graph::PassBuilder& b, Data& d) {
            b.read(depth_image, Access::DepthReadOnly);
            b.write(hdr, Access::ColorAttachment);
            b.read(res.frame_uniforms, Access::UniformRead,
                   graph::Shader::Vertex | graph::Shader::Fragment);
            d = {in, hdr, depth_image};
        },
        [this, pipeline](graph::PassContext& ctx, const Data& d) {
            VkCommandBuffer cmd = ctx.cmd();
            const VkRenderingAttachmentInfo color =
                color_attachment(ctx.view(d.hdr), VK_ATTACHMENT_LOAD_OP_LOAD);
            const VkRenderingAttachmentInfo depth =
                depth_attachment(ctx.view(d.depth), ctx.layout(d.depth), VK_ATTACHMENT_LOAD_OP_LOAD,
                                 VK_ATTACHMENT_STORE_OP_NONE);
            begin_rendering(cmd, ctx.extent(d.hdr), {&color, 1}, &depth);
            set_depth_state(cmd, /*test=*/true, /*write=*/false, d.in.options.closer_or_equal());
            vk::fn().cmd_set_cull_mode(cmd, VK_CULL_MODE_NONE);
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.handle(), 0, 1,
                                    &d.in.frame_set, 0, nullptr);
            vkCmdDraw(cmd, 3, 1, 0, 0);
            vk::fn().cmd_end_rendering(cmd);
        });
}

}  // namespace ds::passes
