#include "renderer/passes/rasterized_count.h"

#include "renderer/gpu_scene/gpu_scene.h"
#include "renderer/shader/compiler.h"
#include "renderer/vk/check.h"
#include "renderer/vk/context.h"
#include "renderer/vk/functions.h"

namespace ds::passes {
namespace {
const VkDescriptorPoolSize kRasterizedCountPoolSizes[] = {{VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1}};
constexpr uint32_t kCountsSet = 2;  // after the frame (0) and material (1) sets draws bind
}  // namespace

RasterizedCount::RasterizedCount(const PassServices& services, const char* pass)
    : services_(services),
      name_(std::string(pass) + "_rasterized"),
      sets_(services.context, 1, kRasterizedCountPoolSizes, "rasterized count sets"),
      pipelines_([this](const Variant& v) { return compile(v); },
                 [this](const Variant& v, const ShaderStages& s, const graph::RenderTarget& t) {
                     return create(v, s, t);
                 }) {
    const VkDescriptorSetLayoutBinding binding =
        vk::layout_binding(0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_FRAGMENT_BIT);
    set_layout_ = vk::DescriptorSetLayout(services.context, {&binding, 1}, "rasterized count set");
    const VkDescriptorSetLayout sets[] = {services.frame_layout, services.material_layout,
                                          set_layout_.handle()};
    layout_ = vk::PipelineLayout(services.context, sets, {}, "rasterized count layout");
}

ShaderStages RasterizedCount::compile(const Variant& v) const {
    shader::Compiler& compiler = services_.compiler;
    ShaderStages s;
    if (v.vertex == Vertex::Shadow)
        s.vert = compiler.compile("shadow.vert", shader::Stage::Vertex).spirv;
    else if (v.vertex == Vertex::SceneNonInvariant)
        s.vert =
            compiler.compile("forward.vert", shader::Stage::Vertex, {{"NON_INVARIANT", "1"}}).spirv;
    else
        s.vert = compiler.compile("depth_prepass.vert", shader::Stage::Vertex).spirv;
    const std::vector<shader::Define> defines = {
        {"SHADOW_VERTEX", v.vertex == Vertex::Shadow ? "1" : "0"}};
    s.frag = compiler.compile("count_rasterized.frag", shader::Stage::Fragment, defines).spirv;
    return s;
}

vk::Pipeline RasterizedCount::create(const Variant& v, const ShaderStages& s,
                                     const graph::RenderTarget& target) const {
    const VertexInputs inputs =
        v.vertex == Vertex::Shadow ? VertexInputs::PositionUv : VertexInputs::All;
    vk::GraphicsPipelineBuilder b =
        scene_pipeline_builder(layout_.handle(), s.vert, s.frag, inputs);
    apply_target(b, target);  // none: counts only
    return b.samples(v.samples).build(services_.context, name_.c_str());
}

void RasterizedCount::add(graph::RenderGraph& graph, const FrameInputs& in,
                          const FrameResources& res, const CountImages& counts,
                          Selection selection) {
    if (!counts.rasterized.valid()) return;
    struct Data {
        FrameInputs in;
        graph::ImageHandle counts;
        Selection selection;
    };
    graph.add_pass<Data>(
        {name_, graph::PassKind::Graphics, graph::PassRole::Measure},
        [&](graph::PassBuilder& b, Data& d) {
            b.read(res.frame_uniforms, graph::Access::UniformRead, graph::Shader::Vertex);
            b.write(counts.rasterized, graph::Access::StorageReadWrite, graph::Shader::Fragment);
            b.render_area(b.extent(counts.rasterized));  // no attachments: counts only
            d = {in, counts.rasterized, std::move(selection)};
        },
        [this](graph::PassContext& ctx, const Data& d) {
            record(ctx, d.in, d.counts, d.selection);
        });
}

void RasterizedCount::record(graph::PassContext& ctx, const FrameInputs& in,
                             graph::ImageHandle counts, const Selection& selection) {
    const VkPipeline pipeline = pipelines_.get({selection.vertex, selection.samples}, ctx.target());
    VkCommandBuffer cmd = ctx.cmd();
    const VkDescriptorSet set = sets_.allocate(in.frame_number, set_layout_.handle());
    const VkDescriptorImageInfo info{VK_NULL_HANDLE, ctx.view(counts), VK_IMAGE_LAYOUT_GENERAL};
    auto write = vk::make<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
    write.dstSet = set;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    write.pImageInfo = &info;
    vkUpdateDescriptorSets(services_.context.device(), 1, &write, 0, nullptr);

    set_depth_state(cmd, /*test=*/false, /*write=*/false, VK_COMPARE_OP_ALWAYS);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    bind_geometry(cmd, *in.scene);
    const VkDescriptorSet sets[] = {in.frame_set};
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.handle(), 0, 1, sets, 0,
                            nullptr);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.handle(), kCountsSet, 1,
                            &set, 0, nullptr);
    std::optional<VkCullModeFlags> cull;
    if (selection.cull != Selection::kEachGroup) cull = selection.cull;
    draw_groups(cmd, *in.scene, layout_.handle(), selection.modes, selection.decals, cull);
}

}  // namespace ds::passes
