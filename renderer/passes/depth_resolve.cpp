#include "renderer/passes/depth_resolve.h"

#include "renderer/shader/compiler.h"
#include "renderer/vk/check.h"
#include "renderer/vk/context.h"
#include "renderer/vk/functions.h"

namespace ds::passes {
namespace {

const VkDescriptorPoolSize kDepthResolvePoolSizes[] = {
    {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1}};
}  // namespace

DepthResolvePass::DepthResolvePass(const PassServices& services, After after)
    : services_(services),
      after_(after),
      nearest_(vk::nearest_clamp_sampler(services.context, "depth resolve nearest")),
      sets_(services.context, 1, kDepthResolvePoolSizes, "depth resolve sets"),
      pipelines_([this](const Variant& v) { return compile(v); },
                 [this](const Variant& v, const ShaderStages& s) { return create(v, s); }) {
    const VkDescriptorSetLayoutBinding binding = vk::layout_binding(
        0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT);
    set_layout_ = vk::DescriptorSetLayout(services.context, {&binding, 1}, "depth resolve set");
    const VkDescriptorSetLayout sets[] = {services.frame_layout, set_layout_.handle()};
    const VkPushConstantRange push{VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(int32_t)};
    layout_ = vk::PipelineLayout(services.context, sets, {&push, 1}, "depth resolve layout");
}

ShaderStages DepthResolvePass::compile(const Variant&) const {
    return compile_fullscreen(services_.compiler, "depth_resolve.frag");
}

vk::Pipeline DepthResolvePass::create(const Variant& v, const ShaderStages& s) const {
    return create_fullscreen(services_.context,
                             {.fragment = "depth_resolve.frag",
                              .depth = v.depth,
                              .layout = layout_.handle(),
                              .name = "depth resolve"},
                             s);
}

void DepthResolvePass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    const FrameOptions& o = in.options;
    // render_path=subpass resolves after the render pass, in this shader: the render pass
    // plans no depth resolve.
    if (!o.msaa() || native_depth_resolve(services_.context.report(), o)) return;
    if ((o.prepass && !o.subpass) != (after_ == After::Prepass)) return;
    const graph::ImageHandle msaa_depth = res.msaa_depth, depth = res.depth;
    graph.add_pass(name(), [&](graph::PassBuilder& b) {
        b.read(res.frame_uniforms, graph::Access::UniformRead,
               graph::Shader::Vertex | graph::Shader::Fragment);
        b.read(msaa_depth, graph::Access::Sampled);
        b.write(depth, graph::Access::DepthAttachment);
        return [this, in, msaa_depth, depth](graph::PassContext& ctx) {
            record(ctx, in, msaa_depth, depth);
        };
    });
}

void DepthResolvePass::record(graph::PassContext& ctx, const FrameInputs& in,
                              graph::ImageHandle msaa_depth, graph::ImageHandle depth) {
    const VkPipeline pipeline = pipelines_.get({.depth = in.options.depth_format});
    const VkDescriptorSet set = sets_.allocate(in.frame_number, set_layout_.handle());
    vk::DescriptorWriter writer;
    writer.image(0, ctx.view(msaa_depth), nearest_.handle(), ctx.layout(msaa_depth));
    writer.update(services_.context.device(), set);
    const VkDescriptorSet sets[] = {in.frame_set, set};
    const int32_t samples = int32_t(in.options.samples);
    draw_fullscreen_depth(ctx, depth, pipeline, layout_.handle(), sets,
                          std::as_bytes(std::span(&samples, 1)));
}

}  // namespace ds::passes
