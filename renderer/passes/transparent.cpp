#include "renderer/passes/transparent.h"

#include <vector>

#include "renderer/gpu_scene/gpu_scene.h"
#include "renderer/passes/scene_draw.h"
#include "renderer/readback/host_readback.h"
#include "renderer/shader/compiler.h"
#include "renderer/vk/context.h"
#include "renderer/vk/functions.h"

namespace ds::passes {

using graph::Access;

namespace {
const VkDescriptorPoolSize kCountPoolSizes[] = {{VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1}};
}

TransparentPass::TransparentPass(const PassServices& services)
    : services_(services),
      lighting_(services.context, services.preferred_depth_format),
      count_layout_(create_count_set_layout(services.context)),
      count_sets_(services.context, 1, kCountPoolSizes, "transparent count sets"),
      pipelines_([this](const Variant& v) { return compile(v); },
                 [this](const Variant& v, const ShaderStages& s) { return create(v, s); }) {
    const VkDescriptorSetLayout sets[] = {services.frame_layout, services.material_layout,
                                          lighting_.layout(), count_layout_.handle()};
    layout_ = vk::PipelineLayout(services.context, sets, {}, "transparent layout");
    pipelines_.get({.depth = services.preferred_depth_format});
}

void TransparentPass::rebuild_pipelines(vk::DestroyList& retired) {
    pipelines_.rebuild(retired);
}

ShaderStages TransparentPass::compile(const Variant& v) const {
    std::vector<shader::Define> defines;
    if (v.counting) defines.push_back({"COUNT_FRAGMENTS", "1"});
    return {services_.compiler.compile("transparent.vert", shader::Stage::Vertex).spirv,
            services_.compiler.compile("transparent.frag", shader::Stage::Fragment, defines).spirv};
}

vk::Pipeline TransparentPass::create(const Variant& v, const ShaderStages& s) const {
    return scene_pipeline_builder(layout_.handle(), s.vert, s.frag)
        .color_attachment(kHdrFormat, vk::Blend::Alpha)
        .depth_attachment(v.depth)
        .samples(v.samples)
        .build(services_.context, "transparent");
}

void TransparentPass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    const VkPipeline pipeline = pipelines_.get({.counting = res.transparent_counts.valid(),
                                                .samples = in.options.samples,
                                                .depth = in.options.depth_format});
    // No prepass normal or roughness: BLEND surfaces are not in the prepass.
    const LightingInputs lighting = {.shadow_map = res.shadow_map,
                                     .normals = {},
                                     .roughness = {},
                                     .ao = res.ao,
                                     .contact_shadows = res.contact_shadows};
    struct Data {
        FrameInputs in;
        FrameResources res;
    };
    graph.add_pass<Data>(
        kName,
        [&](graph::PassBuilder& b, Data& d) {
            declare_hdr_over_depth(b, res, in.options.msaa(), /*resolve=*/true);
            LightingSet::declare(b, lighting);
            b.read(res.frame_uniforms, Access::UniformRead,
                   graph::Shader::Vertex | graph::Shader::Fragment);
            if (res.transparent_counts.valid()) declare_counts(b, res.transparent_counts);
            d = {in, res};
        },
        [this, lighting, pipeline](graph::PassContext& ctx, const Data& d) {
            record(ctx, d.in, d.res, lighting, pipeline);
        });
}

void TransparentPass::collect(const FrameCollect& c, std::span<PassResult> own, FrameResult&) {
    if (!own.empty()) own[0].shaded_fragments = c.readback.u32_sum(c.res.transparent_counts);
}

void TransparentPass::record(graph::PassContext& ctx, const FrameInputs& in,
                             const FrameResources& res, const LightingInputs& lighting,
                             VkPipeline pipeline) {
    VkCommandBuffer cmd = ctx.cmd();
    VkDescriptorSet counts = VK_NULL_HANDLE;
    if (res.transparent_counts.valid()) {
        counts = count_sets_.allocate(in.frame_number, count_layout_.handle());
        write_count_set(services_.context.device(), counts, ctx.view(res.transparent_counts));
    }
    const VkDescriptorSet lighting_set = lighting_.write(ctx, in.frame_number, lighting);
    // msaa > 1: the samples are stored too, for the edge count (MsaaProbe) after the graph.
    begin_hdr_over_depth(ctx, res, in.options.msaa(), /*resolve=*/true);
    set_depth_state(cmd, /*test=*/true, /*write=*/false, in.options.closer_or_equal());
    const std::vector<InstanceDraw> draws =
        sort_back_to_front(*in.scene, in.camera_position, scene_groups(in.options.decal_pass));
    if (!draws.empty()) {
        const VkPipelineLayout layout = layout_.handle();
        bind_geometry(cmd, *in.scene);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &in.frame_set,
                                0, nullptr);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 2, 1, &lighting_set,
                                0, nullptr);
        if (counts)
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, kCountSet, 1,
                                    &counts, 0, nullptr);
        draw_sorted(cmd, *in.scene, layout, draws);
    }
    vk::fn().cmd_end_rendering(cmd);
}

}  // namespace ds::passes
