#include "renderer/passes/overlay_drawing.h"

#include <string>

#include "renderer/passes/scene_draw.h"
#include "renderer/vk/context.h"
#include "renderer/vk/functions.h"

namespace ds::passes {
namespace {}

OverlayDrawing::OverlayDrawing(const PassServices& services, const char* name)
    : services_(services),
      lighting_(services.context, services.preferred_depth_format),
      count_layout_(create_count_set_layout(services.context)),
      count_sets_(services.context, 1, kCountPoolSizes,
                  (std::string(name) + " count sets").c_str()) {
    const VkDescriptorSetLayout sets[] = {services.frame_layout, services.material_layout,
                                          lighting_.layout(), count_layout_.handle()};
    layout_ =
        vk::PipelineLayout(services.context, sets, {}, (std::string(name) + " layout").c_str());
}

std::vector<VkDescriptorSetLayout> OverlayDrawing::set_layouts() const {
    return {services_.frame_layout, services_.material_layout, lighting_.layout(),
            count_layout_.handle()};
}

void OverlayDrawing::add(graph::RenderGraph& graph, const char* name, const FrameInputs& in,
                         FrameResources& res, const CountImages& counts, bool resolve, Draw draw) {
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
        name,
        [&](graph::PassBuilder& b, Data& d) {
            if (in.options.subpass) b.subpass(kSubpassGroup, 1);
            declare_hdr_over_depth(b, res, in.options.msaa(), resolve);
            LightingSet::declare(b, lighting);
            b.read(res.frame_uniforms, graph::Access::UniformRead,
                   graph::Shader::Vertex | graph::Shader::Fragment);
            if (counts.valid()) declare_counts(b, counts);
            d = {in, res};
        },
        [this, lighting, counts, resolve, draw](graph::PassContext& ctx, const Data& d) {
            record(ctx, d.in, d.res, lighting, counts, resolve, draw);
        });
}

void OverlayDrawing::record(graph::PassContext& ctx, const FrameInputs& in,
                            const FrameResources& res, const LightingInputs& lighting,
                            const CountImages& counts, bool resolve, const Draw& draw) {
    VkCommandBuffer cmd = ctx.cmd();
    VkDescriptorSet count_set = VK_NULL_HANDLE;
    if (counts.valid()) {
        count_set = count_sets_.allocate(in.frame_number, count_layout_.handle());
        write_count_set(ctx, services_.context.device(), count_set, counts);
    }
    const VkDescriptorSet lighting_set = lighting_.write(ctx, in.frame_number, lighting);
    const bool own_rendering = !ctx.subpass_target();  // else subpass 1 of the graph's
    if (own_rendering) begin_hdr_over_depth(ctx, res, in.options.msaa(), resolve);
    set_depth_state(cmd, /*test=*/true, /*write=*/false, in.options.closer_or_equal());
    const VkPipelineLayout layout = layout_.handle();
    bind_geometry(cmd, *in.scene);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &in.frame_set, 0,
                            nullptr);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 2, 1, &lighting_set, 0,
                            nullptr);
    if (count_set)
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, kCountSet, 1,
                                &count_set, 0, nullptr);
    draw(cmd, in, layout, nullptr, ctx.subpass_target());
    if (own_rendering) vk::fn().cmd_end_rendering(cmd);
}

void OverlayDrawing::add_history(graph::RenderGraph& graph, const FrameInputs& in,
                                 const FrameResources& res, PixelHistoryReplay& replay, Draw draw) {
    const LightingInputs lighting = {.shadow_map = res.shadow_map,
                                     .normals = {},
                                     .roughness = {},
                                     .ao = res.ao,
                                     .contact_shadows = res.contact_shadows};
    const bool msaa = in.options.msaa();
    const graph::BufferHandle uniforms = res.frame_uniforms;
    replay.add(
        graph, in,
        {.depth = msaa ? res.msaa_depth : res.depth,
         .dst = msaa ? res.msaa_hdr : res.hdr,
         .extent_of = res.depth},
        [lighting, uniforms](graph::PassBuilder& b) {
            LightingSet::declare(b, lighting);
            b.read(uniforms, graph::Access::UniformRead,
                   graph::Shader::Vertex | graph::Shader::Fragment);
        },
        [this, in, lighting, draw, &replay](graph::PassContext& ctx, DrawLog& log) {
            VkCommandBuffer cmd = ctx.cmd();
            const VkDescriptorSet lighting_set = lighting_.write(ctx, in.frame_number, lighting);
            // The replay's layout: binding with the pass's would disturb set 4.
            const VkPipelineLayout layout = replay.layout();
            bind_geometry(cmd, *in.scene);
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1,
                                    &in.frame_set, 0, nullptr);
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 2, 1,
                                    &lighting_set, 0, nullptr);
            draw(cmd, in, layout, &log, {});
        });
}

}  // namespace ds::passes
