#include "renderer/passes/depth_prepass.h"

#include <array>
#include <string>

#include "renderer/gpu_scene.h"
#include "renderer/passes/scene_draw.h"
#include "renderer/shader/compiler.h"
#include "renderer/vk/context.h"
#include "renderer/vk/functions.h"

namespace ds::passes {

using graph::Access;
using scene::AlphaMode;

namespace {
const VkDescriptorPoolSize kCountPoolSizes[] = {{VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1}};
}

DepthPrepass::DepthPrepass(const PassServices& services)
    : services_(services),
      empty_layout_(create_empty_set_layout(services.context)),
      count_layout_(create_count_set_layout(services.context)),
      count_sets_(services.context, 1, kCountPoolSizes, "prepass count sets"),
      pipelines_([this](uint32_t key) { return compile(key); },
                 [this](uint32_t key, const ShaderStages& s) { return create(key, s); }) {
    const VkDescriptorSetLayout sets[] = {services.frame_layout, services.material_layout,
                                          empty_layout_.handle(), count_layout_.handle()};
    layout_ = vk::PipelineLayout(services.context, sets, {}, "depth prepass layout");
    pipelines_.get(kOpaque);
    pipelines_.get(kMask);
}

void DepthPrepass::rebuild_pipelines(vk::DestroyList& retired) {
    pipelines_.rebuild(retired);
}

ShaderStages DepthPrepass::compile(uint32_t key) const {
    std::vector<shader::Define> defines;
    if (key & 3u) defines.push_back({"ALPHA_MASK", std::to_string(key & 3u)});
    if (key & kCounting) defines.push_back({"COUNT_FRAGMENTS", "1"});
    ShaderStages s;
    s.vert = services_.compiler.compile("depth_prepass.vert", shader::Stage::Vertex).spirv;
    s.frag =
        services_.compiler.compile("depth_prepass.frag", shader::Stage::Fragment, defines).spirv;
    return s;
}

vk::Pipeline DepthPrepass::create(uint32_t key, const ShaderStages& s) const {
    static constexpr const char* kNames[] = {"prepass opaque", "prepass mask", "prepass unsplit"};
    return scene_pipeline_builder(layout_.handle(), s.vert, s.frag)
        .color_attachment(kNormalFormat)
        .color_attachment(kRoughnessFormat)
        .depth_attachment(services_.depth_format)
        .build(services_.context, kNames[key & 3u]);
}

void DepthPrepass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    const uint32_t counting = res.prepass_counts.valid() ? kCounting : 0u;
    Draw draw;
    if (in.options.masked_split) {
        draw.opaque = pipelines_.get(kOpaque | counting);
        draw.mask = pipelines_.get(kMask | counting);
    } else {
        draw.opaque = pipelines_.get(kUnsplit | counting);
    }
    struct Data {
        FrameInputs in;
        FrameResources res;
        Draw draw;
    };
    graph.add_pass<Data>(
        kName,
        [&](graph::PassBuilder& b, Data& d) {
            const graph::ImageSize full = graph::ImageSize::relative(1.0f);
            res.normals = b.create_image("normals", {.format = kNormalFormat,
                                                     .size = full,
                                                     .semantic = graph::Semantic::EncodedNormal});
            res.roughness = b.create_image("roughness", {.format = kRoughnessFormat,
                                                         .size = full,
                                                         .semantic = graph::Semantic::UnormScalar});
            b.write(res.depth, Access::DepthAttachment);
            b.write(res.normals, Access::ColorAttachment);
            b.write(res.roughness, Access::ColorAttachment);
            b.read(res.frame_uniforms, Access::UniformRead,
                   graph::Shader::Vertex | graph::Shader::Fragment);
            if (counting) declare_counts(b, res.prepass_counts);
            d = {in, res, draw};
        },
        [this](graph::PassContext& ctx, const Data& d) { record(ctx, d.in, d.res, d.draw); });
}

void DepthPrepass::record(graph::PassContext& ctx, const FrameInputs& in, const FrameResources& res,
                          Draw draw) {
    VkCommandBuffer cmd = ctx.cmd();
    if (res.prepass_counts.valid()) {
        clear_counts(cmd, ctx.image(res.prepass_counts));
        draw.counts = count_sets_.allocate(in.frame_number, count_layout_.handle());
        write_count_set(services_.context.device(), draw.counts, ctx.view(res.prepass_counts));
    }
    // Everything is stored: forward, GTAO, contact shadows and captures read it.
    const std::array<VkRenderingAttachmentInfo, 2> colors = {
        color_attachment(ctx.view(res.normals), VK_ATTACHMENT_LOAD_OP_CLEAR,
                         {0.5f, 0.5f, 0.5f, 0.0f}),  // the zero vector: "no surface"
        color_attachment(ctx.view(res.roughness), VK_ATTACHMENT_LOAD_OP_CLEAR)};
    const VkRenderingAttachmentInfo depth =
        depth_attachment(ctx.view(res.depth), ctx.layout(res.depth), VK_ATTACHMENT_LOAD_OP_CLEAR,
                         VK_ATTACHMENT_STORE_OP_STORE, in.options.far_depth());
    begin_rendering(cmd, ctx.extent(res.depth), colors, &depth);
    set_depth_state(cmd, /*test=*/true, /*write=*/true, in.options.closer());
    bind_geometry(cmd, *in.scene);
    const VkPipelineLayout layout = layout_.handle();
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &in.frame_set, 0,
                            nullptr);
    if (draw.counts)
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, kCountSet, 1,
                                &draw.counts, 0, nullptr);
    // prepass_sort: nearest instances first, so the depth test rejects hidden layers before
    // their (normal-mapped) fragment shader runs; off: instanced groups in authored order.
    auto draw_modes = [&](std::span<const AlphaMode> modes) {
        if (!in.options.prepass_sort) return draw_groups(cmd, *in.scene, layout, modes);
        const auto sorted =
            sort_by_distance(*in.scene, in.camera_position, modes, DrawOrder::FrontToBack);
        return draw_sorted(cmd, *in.scene, layout, sorted);
    };
    if (draw.mask) {
        const AlphaMode opaque[] = {AlphaMode::Opaque};
        const AlphaMode mask[] = {AlphaMode::Mask};
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, draw.opaque);
        draw_modes(opaque);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, draw.mask);
        draw_modes(mask);
    } else {
        // One pipeline with discard for opaque and MASK alike.
        const AlphaMode all[] = {AlphaMode::Opaque, AlphaMode::Mask};
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, draw.opaque);
        draw_modes(all);
    }
    vk::fn().cmd_end_rendering(cmd);
}

}  // namespace ds::passes
