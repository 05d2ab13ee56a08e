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
                 [this](const Variant& v, const ShaderStages& s, const graph::RenderTarget& t) {
                     return create(v, s, t);
                 }) {
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

vk::Pipeline DepthResolvePass::create(const Variant&, const ShaderStages& s,
                                      const graph::RenderTarget& target) const {
    return create_fullscreen(
        services_.context,
        {.fragment = "depth_resolve.frag", .layout = layout_.handle(), .name = "depth resolve"}, s,
        target);
}

void DepthResolvePass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    const FrameOptions& o = in.options;
    // render_path=subpass resolves after the render pass, in this shader: the render pass
    // plans no depth resolve.
    if (!o.msaa() || native_depth_resolve(services_.context.report(), o)) return;
    if ((o.prepass && !o.subpass) != (after_ == After::Prepass)) return;
    struct Data {
        FrameInputs in;
        graph::ImageHandle msaa_depth;
    };
    graph.add_pass<Data>(
        name(),
        [&](graph::PassBuilder& b, Data& d) {
            b.read(res.frame_uniforms, graph::Access::UniformRead,
                   graph::Shader::Vertex | graph::Shader::Fragment);
            d = {in, b.read(res.msaa_depth, graph::Access::Sampled)};
            declare_fullscreen_depth(b, res.depth);
        },
        [this](graph::PassContext& ctx, const Data& d) { record(ctx, d.in, d.msaa_depth); });
}

void DepthResolvePass::record(graph::PassContext& ctx, const FrameInputs& in,
                              graph::ImageHandle msaa_depth) {
    const VkPipeline pipeline = pipelines_.get({}, ctx.target());
    const VkDescriptorSet set = sets_.allocate(in.frame_number, set_layout_.handle());
    vk::DescriptorWriter writer;
    writer.image(0, ctx.view(msaa_depth), nearest_.handle(), ctx.layout(msaa_depth));
    writer.update(services_.context.device(), set);
    const VkDescriptorSet sets[] = {in.frame_set, set};
    const int32_t samples = int32_t(in.options.samples);
    draw_fullscreen_depth(ctx.cmd(), pipeline, layout_.handle(), sets,
                          std::as_bytes(std::span(&samples, 1)));
}

}  // namespace ds::passes
