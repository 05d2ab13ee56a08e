#include "renderer/passes/forward.h"
#include "renderer/vk/functions.h"

#include <algorithm>
#include <numeric>
#include <vector>

#include "renderer/gpu_scene.h"
#include "renderer/shader/compiler.h"
#include "renderer/vk/check.h"
#include "renderer/vk/context.h"

namespace ds::passes {
namespace {

using scene::AlphaMode;

vk::GraphicsPipelineBuilder base_builder(VkPipelineLayout layout, VkFormat depth_format,
                                         const std::vector<uint32_t>& vert,
                                         const std::vector<uint32_t>& frag) {
    vk::GraphicsPipelineBuilder b;
    b.shader(VK_SHADER_STAGE_VERTEX_BIT, vert)
        .shader(VK_SHADER_STAGE_FRAGMENT_BIT, frag)
        .vertex_binding(0, sizeof(scene::Vertex))
        .vertex_attribute(0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(scene::Vertex, position))
        .vertex_attribute(1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(scene::Vertex, normal))
        .vertex_attribute(2, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(scene::Vertex, uv0))
        .vertex_attribute(3, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(scene::Vertex, tangent))
        .depth_attachment(depth_format)
        .layout(layout);
    return b;
}

VkCullModeFlags cull_mode(bool double_sided) {
    return double_sided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
}

}  // namespace

ForwardPass::ForwardPass(vk::Context& context, shader::Compiler& compiler, VkPipelineLayout layout,
                         VkFormat color_format, VkFormat depth_format)
    : context_(context),
      compiler_(compiler),
      layout_(layout),
      color_format_(color_format),
      depth_format_(depth_format) {
    vk::DestroyList nothing_in_flight;
    rebuild_pipelines(nothing_in_flight);
}

void ForwardPass::rebuild_pipelines(vk::DestroyList& retired) {
    using shader::Stage;
    const auto vert = compiler_.compile(kVertexShader, Stage::Vertex).spirv;
    const auto opaque_frag = compiler_.compile(kFragmentShader, Stage::Fragment).spirv;
    const auto mask_frag =
        compiler_.compile(kFragmentShader, Stage::Fragment, {{"ALPHA_MASK", "1"}}).spirv;
    const auto blend_frag =
        compiler_.compile(kFragmentShader, Stage::Fragment, {{"ALPHA_BLEND", "1"}}).spirv;

    vk::Pipeline opaque = base_builder(layout_, depth_format_, vert, opaque_frag)
                              .color_attachment(color_format_)
                              .build(context_, "forward opaque");
    vk::Pipeline mask = base_builder(layout_, depth_format_, vert, mask_frag)
                            .color_attachment(color_format_)
                            .build(context_, "forward mask");
    vk::Pipeline blend = base_builder(layout_, depth_format_, vert, blend_frag)
                             .color_attachment(color_format_, vk::Blend::Alpha)
                             .build(context_, "forward blend");
    if (opaque_) retired.defer(std::move(opaque_));
    if (mask_) retired.defer(std::move(mask_));
    if (blend_) retired.defer(std::move(blend_));
    opaque_ = std::move(opaque);
    mask_ = std::move(mask);
    blend_ = std::move(blend);
}

ForwardStats ForwardPass::record(const ForwardInputs& in) const {
    VkCommandBuffer cmd = in.cmd;
    const VkExtent2D extent = in.color->extent();

    auto color = vk::make<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
    color.imageView = in.color->view();
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    for (int i = 0; i < 4; ++i) color.clearValue.color.float32[i] = in.clear_color[size_t(i)];

    // Reverse-Z: clear to 0 (far), keep the nearest with GREATER. Stored: captures and the
    // next passes read it.
    auto depth = vk::make<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
    depth.imageView = in.depth->view();
    depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    depth.clearValue.depthStencil = {0.0f, 0};

    auto rendering = vk::make<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
    rendering.renderArea = {{0, 0}, extent};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachments = &color;
    rendering.pDepthAttachment = &depth;
    vk::fn().cmd_begin_rendering(cmd, &rendering);

    const VkViewport viewport{0.0f, 0.0f, float(extent.width), float(extent.height), 0.0f, 1.0f};
    const VkRect2D scissor{{0, 0}, extent};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    vk::fn().cmd_set_depth_test_enable(cmd, VK_TRUE);
    vk::fn().cmd_set_depth_write_enable(cmd, VK_TRUE);
    vk::fn().cmd_set_depth_compare_op(cmd, VK_COMPARE_OP_GREATER);

    const VkDeviceSize zero = 0;
    const VkBuffer vertices = in.scene->vertex_buffer();
    vkCmdBindVertexBuffers(cmd, 0, 1, &vertices, &zero);
    vkCmdBindIndexBuffer(cmd, in.scene->index_buffer(), 0, VK_INDEX_TYPE_UINT32);

    ForwardStats stats;
    // Opaque first so MASK (no early-Z guarantee) and BLEND test against its depth.
    draw_groups(in, opaque_.handle(), AlphaMode::Opaque, stats);
    draw_groups(in, mask_.handle(), AlphaMode::Mask, stats);
    draw_blended(in, stats);
    vk::fn().cmd_end_rendering(cmd);
    return stats;
}

void ForwardPass::draw_groups(const ForwardInputs& in, VkPipeline pipeline,
                              scene::AlphaMode alpha_mode, ForwardStats& stats) const {
    VkCommandBuffer cmd = in.cmd;
    bool bound = false;
    uint32_t material = UINT32_MAX;
    for (const scene::DrawGroup& g : in.scene->draw_groups()) {
        if (g.alpha_mode != alpha_mode || g.instance_count == 0) continue;
        const GpuMesh& mesh = in.scene->meshes()[g.mesh];
        if (mesh.index_count == 0) continue;
        if (!bound) {  // bind lazily: a frame without MASK groups never touches that pipeline
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1,
                                    &in.frame_set, 0, nullptr);
            bound = true;
        }
        if (mesh.material != material) {
            material = mesh.material;
            const VkDescriptorSet set = in.scene->material_set(material);
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 1, 1, &set, 0,
                                    nullptr);
        }
        vk::fn().cmd_set_cull_mode(cmd, cull_mode(g.double_sided));
        // gl_InstanceIndex = first_instance + i indexes the instance buffer directly.
        vkCmdDrawIndexed(cmd, mesh.index_count, g.instance_count, mesh.first_index,
                         mesh.vertex_offset, g.first_instance);
        ++stats.draw_calls;
        stats.instances += g.instance_count;
        (alpha_mode == AlphaMode::Opaque ? stats.opaque_groups : stats.mask_groups)++;
    }
}

void ForwardPass::draw_blended(const ForwardInputs& in, ForwardStats& stats) const {
    struct Item {
        float distance;
        uint32_t instance;
        const scene::DrawGroup* group;
    };
    std::vector<Item> items;
    const auto& centers = in.scene->instance_centers();
    for (const scene::DrawGroup& g : in.scene->draw_groups()) {
        if (g.alpha_mode != AlphaMode::Blend) continue;
        if (in.scene->meshes()[g.mesh].index_count == 0) continue;
        for (uint32_t i = g.first_instance; i < g.first_instance + g.instance_count; ++i)
            items.push_back({glm::distance(centers[i], in.camera_position), i, &g});
    }
    if (items.empty()) return;
    // Back to front; the instance index breaks ties so the order (and the image) is stable.
    std::sort(items.begin(), items.end(), [](const Item& a, const Item& b) {
        return a.distance != b.distance ? a.distance > b.distance : a.instance < b.instance;
    });

    VkCommandBuffer cmd = in.cmd;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, blend_.handle());
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &in.frame_set, 0,
                            nullptr);
    vk::fn().cmd_set_depth_write_enable(cmd,
                                        VK_FALSE);  // test against opaque, never occlude each other
    uint32_t material = UINT32_MAX;
    for (const Item& item : items) {
        const GpuMesh& mesh = in.scene->meshes()[item.group->mesh];
        if (mesh.material != material) {
            material = mesh.material;
            const VkDescriptorSet set = in.scene->material_set(material);
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 1, 1, &set, 0,
                                    nullptr);
        }
        vk::fn().cmd_set_cull_mode(cmd, cull_mode(item.group->double_sided));
        vkCmdDrawIndexed(cmd, mesh.index_count, 1, mesh.first_index, mesh.vertex_offset,
                         item.instance);
        ++stats.draw_calls;
        ++stats.instances;
        ++stats.blend_instances;
    }
}

}  // namespace ds::passes
