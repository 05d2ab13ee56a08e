#include "renderer/passes/scene_draw.h"

#include <algorithm>
#include <limits>

#include "renderer/gpu_scene/gpu_scene.h"
#include "renderer/passes/draw_queries.h"
#include "renderer/vk/functions.h"

namespace ds::passes {

vk::GraphicsPipelineBuilder scene_pipeline_builder(VkPipelineLayout layout,
                                                   std::span<const uint32_t> vert,
                                                   std::span<const uint32_t> frag,
                                                   VertexInputs inputs) {
    vk::GraphicsPipelineBuilder b;
    b.shader(VK_SHADER_STAGE_VERTEX_BIT, vert);
    if (!frag.empty()) b.shader(VK_SHADER_STAGE_FRAGMENT_BIT, frag);
    b.vertex_binding(0, sizeof(scene::Vertex))
        .vertex_attribute(0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(scene::Vertex, position))
        .layout(layout);
    if (inputs != VertexInputs::Position)
        b.vertex_attribute(2, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(scene::Vertex, uv0));
    if (inputs == VertexInputs::All) {
        b.vertex_attribute(1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(scene::Vertex, normal))
            .vertex_attribute(3, 0, VK_FORMAT_R32G32B32A32_SFLOAT,
                              offsetof(scene::Vertex, tangent));
    }
    return b;
}

VkCullModeFlags cull_mode(bool double_sided) {
    return double_sided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
}

void bind_geometry(VkCommandBuffer cmd, const GpuScene& scene) {
    const VkDeviceSize zero = 0;
    const VkBuffer vertices = scene.vertex_buffer();
    vkCmdBindVertexBuffers(cmd, 0, 1, &vertices, &zero);
    vkCmdBindIndexBuffer(cmd, scene.index_buffer(), 0, VK_INDEX_TYPE_UINT32);
}

namespace {

// Binds set 1 when the material differs from the one bound last.
void bind_material(VkCommandBuffer cmd, const GpuScene& scene, VkPipelineLayout layout,
                   uint32_t material, uint32_t& bound) {
    if (material == bound) return;
    bound = material;
    const VkDescriptorSet set = scene.material_set(material);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 1, 1, &set, 0, nullptr);
}

}  // namespace

bool selected(const scene::DrawGroup& group, std::span<const scene::AlphaMode> modes,
              Decals decals) {
    if (std::find(modes.begin(), modes.end(), group.alpha_mode) == modes.end()) return false;
    switch (decals) {
        case Decals::Include:
            return true;
        case Decals::Exclude:
            return !group.decal;
        case Decals::Only:
            return group.decal;
    }
    return false;
}

DrawCounts draw_groups(VkCommandBuffer cmd, const GpuScene& scene, VkPipelineLayout layout,
                       std::span<const scene::AlphaMode> modes, Decals decals,
                       std::optional<VkCullModeFlags> cull, DrawHooks hooks) {
    DrawQueries* queries = hooks.queries && hooks.queries->on() ? hooks.queries : nullptr;
    DrawCounts counts;
    uint32_t material = UINT32_MAX;
    for (const scene::DrawGroup& g : scene.draw_groups()) {
        if (!selected(g, modes, decals)) continue;
        const GpuMesh& mesh = scene.meshes()[g.mesh];
        if (g.instance_count == 0 || mesh.index_count == 0) continue;
        bind_material(cmd, scene, layout, mesh.material, material);
        vk::fn().cmd_set_cull_mode(cmd, cull.value_or(cull_mode(g.double_sided)));
        // gl_InstanceIndex = first_instance + i indexes the instance buffer directly.
        const uint32_t group = uint32_t(&g - scene.draw_groups().data());
        scene.begin_group_label(cmd, group);
        if (queries) queries->begin(cmd, group);
        vkCmdDrawIndexed(cmd, mesh.index_count, g.instance_count, mesh.first_index,
                         mesh.vertex_offset, g.first_instance);
        if (queries) queries->end(cmd);
        scene.end_group_label(cmd);
        if (hooks.log) hooks.log->add(g.first_instance, g.instance_count);
        ++counts.draws;
        counts.instances += g.instance_count;
    }
    return counts;
}

namespace {

// A draw and the distance it is sorted by (the two sorts below).
struct DistanceDraw {
    float distance;
    InstanceDraw draw;
};

std::vector<InstanceDraw> draws_of(const std::vector<DistanceDraw>& items) {
    std::vector<InstanceDraw> draws;
    draws.reserve(items.size());
    for (const DistanceDraw& item : items) draws.push_back(item.draw);
    return draws;
}

}  // namespace

std::vector<InstanceDraw> sort_by_distance(const GpuScene& scene, glm::vec3 camera,
                                           std::span<const scene::AlphaMode> modes, DrawOrder order,
                                           Decals decals) {
    std::vector<DistanceDraw> items;
    const auto& centers = scene.instance_centers();
    for (const scene::DrawGroup& g : scene.draw_groups()) {
        if (!selected(g, modes, decals)) continue;
        if (scene.meshes()[g.mesh].index_count == 0) continue;
        for (uint32_t i = g.first_instance; i < g.first_instance + g.instance_count; ++i)
            items.push_back({glm::distance(centers[i], camera), {i, &g}});
    }
    const bool back_to_front = order == DrawOrder::BackToFront;
    std::sort(items.begin(), items.end(), [&](const DistanceDraw& a, const DistanceDraw& b) {
        if (a.distance != b.distance) {
            return back_to_front ? a.distance > b.distance : a.distance < b.distance;
        }
        return a.draw.instance < b.draw.instance;
    });
    return draws_of(items);
}

std::vector<InstanceDraw> sort_groups_front_to_back(const GpuScene& scene, glm::vec3 camera,
                                                    std::span<const scene::AlphaMode> modes,
                                                    Decals decals) {
    std::vector<DistanceDraw> items;
    const auto& centers = scene.instance_centers();
    for (const scene::DrawGroup& g : scene.draw_groups()) {
        if (!selected(g, modes, decals) || g.instance_count == 0) continue;
        if (scene.meshes()[g.mesh].index_count == 0) continue;
        float nearest = std::numeric_limits<float>::max();
        for (uint32_t i = g.first_instance; i < g.first_instance + g.instance_count; ++i)
            nearest = std::min(nearest, glm::distance(centers[i], camera));
        items.push_back({nearest, {g.first_instance, &g, g.instance_count}});
    }
    // Groups are in the scene's order already: a stable sort keeps it for equal distances.
    std::stable_sort(items.begin(), items.end(), [](const DistanceDraw& a, const DistanceDraw& b) {
        return a.distance < b.distance;
    });
    return draws_of(items);
}

std::vector<InstanceDraw> sort_back_to_front(const GpuScene& scene, glm::vec3 camera,
                                             Decals decals) {
    const scene::AlphaMode blend[] = {scene::AlphaMode::Blend};
    return sort_by_distance(scene, camera, blend, DrawOrder::BackToFront, decals);
}

DrawCounts draw_sorted(VkCommandBuffer cmd, const GpuScene& scene, VkPipelineLayout layout,
                       std::span<const InstanceDraw> draws, DrawHooks hooks) {
    DrawQueries* queries = hooks.queries && hooks.queries->on() ? hooks.queries : nullptr;
    DrawCounts counts;
    uint32_t material = UINT32_MAX;
    for (const InstanceDraw& d : draws) {
        const GpuMesh& mesh = scene.meshes()[d.group->mesh];
        bind_material(cmd, scene, layout, mesh.material, material);
        vk::fn().cmd_set_cull_mode(cmd, cull_mode(d.group->double_sided));
        const uint32_t group = uint32_t(d.group - scene.draw_groups().data());
        scene.begin_group_label(cmd, group);
        if (queries) queries->begin(cmd, group);
        vkCmdDrawIndexed(cmd, mesh.index_count, d.count, mesh.first_index, mesh.vertex_offset,
                         d.instance);
        if (queries) queries->end(cmd);
        scene.end_group_label(cmd);
        if (hooks.log) hooks.log->add(d.instance, d.count);
        ++counts.draws;
        counts.instances += d.count;
    }
    return counts;
}

}  // namespace ds::passes
