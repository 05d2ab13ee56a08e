#include "renderer/passes/tonemap.h"

#include "renderer/shader/compiler.h"
#include "renderer/vk/check.h"
#include "renderer/vk/context.h"
#include "renderer/vk/functions.h"

namespace ds::passes {

using graph::Access;

namespace {
const VkDescriptorPoolSize kTonemapPoolSizes[] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1}};
}

TonemapPass::TonemapPass(const PassServices& services)
    : services_(services),
      sets_(services.context, 1, kTonemapPoolSizes, "tonemap sets"),
      pipelines_([this](const NoVariant& v) { return compile(v); },
                 [this](const NoVariant& v, const ShaderStages& s, const graph::RenderTarget& t) {
                     return create(v, s, t);
                 }) {
    const VkDescriptorSetLayoutBinding hdr = vk::layout_binding(
        0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT);
    hdr_layout_ = vk::DescriptorSetLayout(services.context, {&hdr, 1}, "tonemap set layout");
    const VkDescriptorSetLayout sets[] = {services.frame_layout, hdr_layout_.handle()};
    layout_ = vk::PipelineLayout(services.context, sets, {}, "tonemap layout");
    nearest_ = vk::nearest_clamp_sampler(services.context, "tonemap nearest");
    pipelines_.info({});
}

void TonemapPass::rebuild_pipelines(vk::DestroyList& retired) {
    pipelines_.rebuild(retired);
}

ShaderStages TonemapPass::compile(const NoVariant&) const {
    return compile_fullscreen(services_.compiler, "tonemap.frag");
}

vk::Pipeline TonemapPass::create(const NoVariant&, const ShaderStages& s,
                                 const graph::RenderTarget& target) const {
    return create_fullscreen(
        services_.context,
        {.fragment = "tonemap.frag", .layout = layout_.handle(), .name = "tonemap"}, s, target);
}

void TonemapPass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    pipelines_.info({});
    struct Data {
        FrameInputs in;
        FrameResources res;
    };
    graph.add_pass<Data>(
        kName,
        [&](graph::PassBuilder& b, Data& d) {
            b.read(res.hdr, Access::Sampled, graph::Shader::Fragment);
            // Every pixel is written: the old contents need not be loaded.
            b.color(res.final_image, {.load = graph::Load::DontCare});
            b.read(res.frame_uniforms, Access::UniformRead,
                   graph::Shader::Vertex | graph::Shader::Fragment);
            d = {in, res};
        },
        [this](graph::PassContext& ctx, const Data& d) {
            VkCommandBuffer cmd = ctx.cmd();
            const VkDescriptorSet set = sets_.allocate(d.in.frame_number, hdr_layout_.handle());
            vk::DescriptorWriter writer;
            writer.image(0, ctx.view(d.res.hdr), nearest_.handle(), ctx.layout(d.res.hdr));
            writer.update(services_.context.device(), set);
            set_depth_state(cmd, /*test=*/false, /*write=*/false, VK_COMPARE_OP_ALWAYS);
            vk::fn().cmd_set_cull_mode(cmd, VK_CULL_MODE_NONE);
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                              pipelines_.get({}, ctx.target()));
            const VkDescriptorSet sets[] = {d.in.frame_set, set};
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.handle(), 0, 2,
                                    sets, 0, nullptr);
            vkCmdDraw(cmd, 3, 1, 0, 0);
        });
}

}  // namespace ds::passes
