#include "renderer/passes/skybox.h"

#include "renderer/shader/compiler.h"
#include "renderer/vk/context.h"
#include "renderer/vk/functions.h"

namespace ds::passes {

using graph::Access;

SkyboxPass::SkyboxPass(const PassServices& services)
    : services_(services),
      pipelines_([this](const Variant& v) { return compile(v); },
                 [this](const Variant& v, const ShaderStages& s) { return create(v, s); }) {
    const VkDescriptorSetLayout sets[] = {services.frame_layout};
    layout_ = vk::PipelineLayout(services.context, sets, {}, "skybox layout");
    pipelines_.get({.depth = services.preferred_depth_format});
}

void SkyboxPass::rebuild_pipelines(vk::DestroyList& retired) {
    pipelines_.rebuild(retired);
}

ShaderStages SkyboxPass::compile(const Variant&) const {
    return compile_fullscreen(services_.compiler, "skybox.frag");
}

vk::Pipeline SkyboxPass::create(const Variant& v, const ShaderStages& s) const {
    return create_fullscreen(services_.context,
                             {.fragment = "skybox.frag",
                              .color = kHdrFormat,
                              .depth = v.depth,
                              .samples = v.samples,
                              .layout = layout_.handle(),
                              .name = "skybox",
                              .render_pass = v.render_pass,
                              .subpass = v.subpass},
                             s);
}

std::vector<SettingDef> SkyboxPass::knobs() {
    return {bool_knob(kKnob, "passes", true, "procedural sky behind the geometry",
                      Invalidates::Nothing)};
}

void SkyboxPass::configure(const FrameSetup& setup, FrameOptions& o) {
    o.sky = knob_value(setup.settings, kKnob);
    if (!o.sky) set_skipped("sky=off");
}

void SkyboxPass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    if (!in.options.sky) return;
    const Variant variant{.samples = in.options.samples, .depth = in.options.depth_format};
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
            if (in.options.subpass) b.subpass(kSubpassGroup, 1);
            b.read(depth_image, Access::DepthReadOnly);
            b.write(hdr, Access::ColorAttachment);
            b.read(res.frame_uniforms, Access::UniformRead,
                   graph::Shader::Vertex | graph::Shader::Fragment);
            d = {in, hdr, depth_image};
        },
        [this, variant](graph::PassContext& ctx, const Data& d) {
            VkCommandBuffer cmd = ctx.cmd();
            Variant v = variant;
            const graph::SubpassTarget target = ctx.subpass_target();  // empty: own rendering
            v.render_pass = target.pass;
            v.subpass = target.index;
            const VkPipeline pipeline = pipelines_.get(v);
            if (!v.render_pass) {
                const VkRenderingAttachmentInfo color =
                    color_attachment(ctx.view(d.hdr), VK_ATTACHMENT_LOAD_OP_LOAD);
                const VkRenderingAttachmentInfo depth =
                    depth_attachment(ctx.view(d.depth), ctx.layout(d.depth),
                                     VK_ATTACHMENT_LOAD_OP_LOAD, VK_ATTACHMENT_STORE_OP_NONE);
                begin_rendering(cmd, ctx.extent(d.hdr), {&color, 1}, &depth);
            }
            set_depth_state(cmd, /*test=*/true, /*write=*/false, d.in.options.closer_or_equal());
            vk::fn().cmd_set_cull_mode(cmd, VK_CULL_MODE_NONE);
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.handle(), 0, 1,
                                    &d.in.frame_set, 0, nullptr);
            vkCmdDraw(cmd, 3, 1, 0, 0);
            if (!v.render_pass) vk::fn().cmd_end_rendering(cmd);
        });
}

}  // namespace ds::passes
