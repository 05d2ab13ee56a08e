#include "renderer/passes/skybox.h"

#include "renderer/shader/compiler.h"
#include "renderer/vk/context.h"
#include "renderer/vk/functions.h"

namespace ds::passes {

using graph::Access;

SkyboxPass::SkyboxPass(const PassServices& services)
    : services_(services),
      pipelines_([this](const Variant& v) { return compile(v); },
                 [this](const Variant& v, const ShaderStages& s, const graph::RenderTarget& t) {
                     return create(v, s, t);
                 }) {
    const VkDescriptorSetLayout sets[] = {services.frame_layout};
    layout_ = vk::PipelineLayout(services.context, sets, {}, "skybox layout");
    pipelines_.info({});
}

void SkyboxPass::rebuild_pipelines(vk::DestroyList& retired) {
    pipelines_.rebuild(retired);
}

ShaderStages SkyboxPass::compile(const Variant&) const {
    return compile_fullscreen(services_.compiler, "skybox.frag");
}

vk::Pipeline SkyboxPass::create(const Variant& v, const ShaderStages& s,
                                const graph::RenderTarget& target) const {
    return create_fullscreen(services_.context,
                             {.fragment = "skybox.frag",
                              .samples = v.samples,
                              .layout = layout_.handle(),
                              .name = "skybox"},
                             s, target);
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
    const Variant variant{.samples = in.options.samples};
    // msaa > 1: into the multisampled colour, against the multisampled depth, before
    // transparent resolves: a silhouette pixel's sky samples blend with its surface samples.
    const bool msaa = in.options.msaa();
    struct Data {
        FrameInputs in;
    };
    graph.add_pass<Data>(
        kName,
        [&](graph::PassBuilder& b, Data& d) {
            b.depth(msaa ? res.msaa_depth : res.depth, {.read_only = true});
            b.color(msaa ? res.msaa_hdr : res.hdr);
            b.read(res.frame_uniforms, Access::UniformRead,
                   graph::Shader::Vertex | graph::Shader::Fragment);
            d = {in};
        },
        [this, variant](graph::PassContext& ctx, const Data& d) {
            VkCommandBuffer cmd = ctx.cmd();
            set_depth_state(cmd, /*test=*/true, /*write=*/false, d.in.options.closer_or_equal());
            vk::fn().cmd_set_cull_mode(cmd, VK_CULL_MODE_NONE);
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                              pipelines_.get(variant, ctx.target()));
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.handle(), 0, 1,
                                    &d.in.frame_set, 0, nullptr);
            vkCmdDraw(cmd, 3, 1, 0, 0);
        });
}

}  // namespace ds::passes
