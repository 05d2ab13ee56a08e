#include "renderer/passes/zfight_bound.h"

#include "renderer/format/format.h"
#include "renderer/shader/compiler.h"
#include "renderer/vk/context.h"

namespace ds::passes {
namespace {

const VkDescriptorPoolSize kZfightBoundPoolSizes[] = {
    {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1}};

struct BoundPush {
    uint32_t steps, depth_bits;
};

}  // namespace

ZfightBound::ZfightBound(const PassServices& services)
    : services_(services),
      nearest_(vk::nearest_clamp_sampler(services.context, "zfight bound nearest")),
      sets_(services.context, 1, kZfightBoundPoolSizes, "zfight bound sets"),
      pipelines_(
          [this](const Variant& v) {
              if (!v.per_sample())
                  return compile_fullscreen(services_.compiler, "zfight_bound.frag");
              return ShaderStages{
                  services_.compiler.compile("fullscreen.vert", shader::Stage::Vertex).spirv,
                  services_.compiler
                      .compile("zfight_bound.frag", shader::Stage::Fragment, {{"PER_SAMPLE", "1"}})
                      .spirv};
          },
          [this](const Variant& v, const ShaderStages& s, const graph::RenderTarget& target) {
              return create_fullscreen(services_.context,
                                       {.fragment = "zfight_bound.frag",
                                        .samples = v.samples,
                                        .layout = layout_.handle(),
                                        .name = "zfight bound"},
                                       s, target);
          }) {
    const VkDescriptorSetLayoutBinding binding = vk::layout_binding(
        0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT);
    set_layout_ = vk::DescriptorSetLayout(services.context, {&binding, 1}, "zfight bound set");
    const VkDescriptorSetLayout sets[] = {services.frame_layout, set_layout_.handle()};
    const VkPushConstantRange push{VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(BoundPush)};
    layout_ = vk::PipelineLayout(services.context, sets, {&push, 1}, "zfight bound layout");
}

graph::ImageHandle ZfightBound::add(graph::RenderGraph& graph, const FrameInputs& in,
                                    const FrameResources& res, uint32_t steps) {
    const graph::ImageHandle stored = in.options.msaa() ? res.msaa_depth : res.depth;
    struct Data {
        FrameInputs in;
        graph::ImageHandle stored, bound;
    };
    const Data& data = graph.add_pass<Data>(
        "zfight_bound",
        [&](graph::PassBuilder& b, Data& d) {
            const graph::ImageHandle bound =
                b.create_image("zfight_bound",
                               {.format = in.options.depth_format,
                                .size = graph::ImageSize::relative(1.0f),
                                .samples = in.options.samples,
                                .semantic = in.options.reverse_z ? graph::Semantic::ReverseZDepth
                                                                 : graph::Semantic::ForwardZDepth});
            b.read(res.frame_uniforms, graph::Access::UniformRead,
                   graph::Shader::Vertex | graph::Shader::Fragment);
            b.read(stored, graph::Access::Sampled);
            declare_fullscreen_depth(b, bound);
            d = {in, stored, bound};
        },
        [this, steps](graph::PassContext& ctx, const Data& d) {
            record(ctx, d.in, steps, d.stored);
        });
    return data.bound;
}

void ZfightBound::record(graph::PassContext& ctx, const FrameInputs& in, uint32_t steps,
                         graph::ImageHandle stored) {
    const VkDescriptorSet set = sets_.allocate(in.frame_number, set_layout_.handle());
    vk::DescriptorWriter writer;
    writer.image(0, ctx.view(stored), nearest_.handle(), ctx.layout(stored));
    writer.update(services_.context.device(), set);
    const VkDescriptorSet sets[] = {in.frame_set, set};
    const BoundPush push{steps, format::depth_bits(in.options.depth_format)};
    const Variant variant{.samples = in.options.samples};
    draw_fullscreen_depth(ctx.cmd(), pipelines_.get(variant, ctx.target()), layout_.handle(), sets,
                          std::as_bytes(std::span(&push, 1)));
}

}  // namespace ds::passes
