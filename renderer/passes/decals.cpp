#include "renderer/passes/decals.h"

#include <vector>

#include "renderer/gpu_scene/gpu_scene.h"
#include "renderer/passes/scene_draw.h"
#include "renderer/readback/host_readback.h"
#include "renderer/shader/compiler.h"
#include "renderer/vk/context.h"
#include "renderer/vk/functions.h"

namespace ds::passes {

using graph::Access;
using scene::AlphaMode;

namespace {

const VkDescriptorPoolSize kCountPoolSizes[] = {{VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1}};

// Towards the camera: 4 steps of the depth format plus one pixel's depth slope.
constexpr float kBiasSteps = 4.0f;
constexpr float kBiasSlope = 1.0f;

}  // namespace

DecalsPass::DecalsPass(const PassServices& services)
    : services_(services),
      lighting_(services.context, services.preferred_depth_format),
      count_layout_(create_count_set_layout(services.context)),
      count_sets_(services.context, 1, kCountPoolSizes, "decals count sets"),
      pipelines_([this](const Variant& v) { return compile(v); },
                 [this](const Variant& v, const ShaderStages& s) { return create(v, s); }) {
    const VkDescriptorSetLayout sets[] = {services.frame_layout, services.material_layout,
                                          lighting_.layout(), count_layout_.handle()};
    layout_ = vk::PipelineLayout(services.context, sets, {}, "decals layout");
}

ShaderStages DecalsPass::compile(const Variant& v) const {
    std::vector<shader::Define> defines = {{"ALPHA_MODE", std::to_string(int(v.mode))}};
    if (v.counting) defines.push_back({"COUNT_FRAGMENTS", "1"});
    return {services_.compiler.compile("transparent.vert", shader::Stage::Vertex).spirv,
            services_.compiler.compile("transparent.frag", shader::Stage::Fragment, defines).spirv};
}

vk::Pipeline DecalsPass::create(const Variant& v, const ShaderStages& s) const {
    const float towards_camera = v.reverse_z ? 1.0f : -1.0f;
    return scene_pipeline_builder(layout_.handle(), s.vert, s.frag)
        .color_attachment(kHdrFormat,
                          v.mode == AlphaMode::Blend ? vk::Blend::Alpha : vk::Blend::None)
        .depth_attachment(v.depth)
        .samples(v.samples)
        .depth_bias(towards_camera * kBiasSteps, towards_camera * kBiasSlope)
        .build(services_.context, "decals");
}

void DecalsPass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    if (!in.options.decal_pass) return;
    auto pipeline = [&](AlphaMode mode) {
        return pipelines_.get({.mode = mode,
                               .counting = res.decal_counts.valid(),
                               .reverse_z = in.options.reverse_z,
                               .samples = in.options.samples,
                               .depth = in.options.depth_format});
    };
    const Pipelines pipelines = {pipeline(AlphaMode::Opaque), pipeline(AlphaMode::Mask),
                                 pipeline(AlphaMode::Blend)};
    // Not in the prepass: no prepass normal or roughness.
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
            declare_hdr_over_depth(b, res, in.options.msaa(), /*resolve=*/false);
            LightingSet::declare(b, lighting);
            b.read(res.frame_uniforms, Access::UniformRead,
                   graph::Shader::Vertex | graph::Shader::Fragment);
            if (res.decal_counts.valid()) declare_counts(b, res.decal_counts);
            d = {in, res};
        },
        [this, lighting, pipelines](graph::PassContext& ctx, const Data& d) {
            record(ctx, d.in, d.res, lighting, pipelines);
        });
}

void DecalsPass::collect(const FrameCollect& c, std::span<PassResult> own, FrameResult&) {
    if (!own.empty()) own[0].shaded_fragments = c.readback.u32_sum(c.res.decal_counts);
}

void DecalsPass::record(graph::PassContext& ctx, const FrameInputs& in, const FrameResources& res,
                        const LightingInputs& lighting, const Pipelines& pipelines) {
    VkCommandBuffer cmd = ctx.cmd();
    VkDescriptorSet counts = VK_NULL_HANDLE;
    if (res.decal_counts.valid()) {
        counts = count_sets_.allocate(in.frame_number, count_layout_.handle());
        write_count_set(services_.context.device(), counts, ctx.view(res.decal_counts));
    }
    const VkDescriptorSet lighting_set = lighting_.write(ctx, in.frame_number, lighting);
    begin_hdr_over_depth(ctx, res, in.options.msaa(), /*resolve=*/false);
    set_depth_state(cmd, /*test=*/true, /*write=*/false, in.options.closer_or_equal());
    const VkPipelineLayout layout = layout_.handle();
    bind_geometry(cmd, *in.scene);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &in.frame_set, 0,
                            nullptr);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 2, 1, &lighting_set, 0,
                            nullptr);
    if (counts)
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, kCountSet, 1, &counts,
                                0, nullptr);
    const std::pair<AlphaMode, VkPipeline> order[] = {{AlphaMode::Opaque, pipelines.opaque},
                                                      {AlphaMode::Mask, pipelines.mask},
                                                      {AlphaMode::Blend, pipelines.blend}};
    for (const auto& [mode, pipeline] : order) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
        draw_groups(cmd, *in.scene, layout, {&mode, 1}, Decals::Only);
    }
    vk::fn().cmd_end_rendering(cmd);
}

}  // namespace ds::passes
