#pragma once
// Drawing scene meshes, shared by the passes that do (shadow, depth_prepass, forward,
// transparent): the vertex layout, instanced draw groups (seed 000: one draw per group,
// cull mode per group), BLEND instances back to front.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>
#include <glm/glm.hpp>

#include "renderer/scene/scene.h"
#include "renderer/vk/pipeline.h"

namespace ds {
class GpuScene;
}

namespace ds::passes {

// Which vertex attributes the vertex shader reads: unread ones draw performance warnings.
enum class VertexInputs : uint8_t {
    All,         // position, normal, uv0, tangent (shaders/common/scene_vertex.glsl)
    PositionUv,  // shaders/shadow.vert; the masked depth-only prepass (SCENE_VARYINGS=1)
    Position,    // the opaque depth-only prepass (SCENE_VARYINGS=0)
};

// Pipeline builder with the scene's vertex layout; `frag` may be empty (depth only).
vk::GraphicsPipelineBuilder scene_pipeline_builder(VkPipelineLayout layout,
                                                   std::span<const uint32_t> vert,
                                                   std::span<const uint32_t> frag,
                                                   VertexInputs inputs = VertexInputs::All);

VkCullModeFlags cull_mode(bool double_sided);

// Binds the scene's vertex and index buffers.
void bind_geometry(VkCommandBuffer cmd, const GpuScene& scene);

// Which draw groups a pass draws. Coplanar overlays (scene::DrawGroup::decal) are the decals
// pass's when it runs (FrameOptions::decal_pass) and drawn like any surface otherwise.
enum class Decals : uint8_t { Include, Exclude, Only };
// What the scene's own passes (shadow, prepass, forward, zfight, transparent) draw.
inline Decals scene_groups(bool decal_pass) {
    return decal_pass ? Decals::Exclude : Decals::Include;
}
bool selected(const scene::DrawGroup& group, std::span<const scene::AlphaMode> modes,
              Decals decals);

struct DrawCounts {
    uint32_t draws = 0;
    uint32_t instances = 0;
};

class DrawQueries;
// The draws a pass recorded, in submission order (pixel history maps a fragment's instance to
// its draw through it, so the history's order is the one the pass draws in, not a copy of it).
// `pipeline` is the caller's tag for the draws that follow (which pipeline it bound).
struct DrawLog {
    struct Draw {
        uint32_t first_instance = 0, instance_count = 0;
        uint32_t pipeline = 0;
    };
    std::vector<Draw> draws;
    uint32_t pipeline = 0;
    void add(uint32_t first_instance, uint32_t instance_count) {
        draws.push_back({first_instance, instance_count, pipeline});
    }
};

// One instanced draw per group whose alpha mode is in `modes`, in the scene's authored
// order. Set 1 is bound when the material changes; the cull mode follows each group's
// double_sided flag unless `cull` overrides it. The caller has bound the pipeline and set 0.
// What a draw call may carry besides the draw: with `queries` (count_draws) each draw is inside
// an occlusion query of its group; with `log` (pixel history) each draw is appended to it.
struct DrawHooks {
    DrawQueries* queries = nullptr;
    DrawLog* log = nullptr;
};
DrawCounts draw_groups(VkCommandBuffer cmd, const GpuScene& scene, VkPipelineLayout layout,
                       std::span<const scene::AlphaMode> modes, Decals decals,
                       std::optional<VkCullModeFlags> cull = std::nullopt, DrawHooks hooks = {});

// One instance (or `count` consecutive instances of one group), in the order it must be drawn.
struct InstanceDraw {
    uint32_t instance = 0;
    const scene::DrawGroup* group = nullptr;
    uint32_t count = 1;
};
enum class DrawOrder { FrontToBack, BackToFront };
// Every instance whose alpha mode is in `modes`, ordered by the distance of its bounds'
// centre from `camera`; the instance index breaks ties so the order (and the image) is stable.
std::vector<InstanceDraw> sort_by_distance(const GpuScene& scene, glm::vec3 camera,
                                           std::span<const scene::AlphaMode> modes, DrawOrder order,
                                           Decals decals);
// Every selected group as one instanced draw, nearest first by its nearest instance's centre
// (the group index breaks ties): front to back at the granularity of draw calls, for a pass
// whose fragments cost less than extra draws (the Z-only prepass).
std::vector<InstanceDraw> sort_groups_front_to_back(const GpuScene& scene, glm::vec3 camera,
                                                    std::span<const scene::AlphaMode> modes,
                                                    Decals decals);
// Every BLEND instance, back to front (the order blending needs).
std::vector<InstanceDraw> sort_back_to_front(const GpuScene& scene, glm::vec3 camera,
                                             Decals decals);
// Draws them in order, each its `count` instances (the order is per draw, not per group).
DrawCounts draw_sorted(VkCommandBuffer cmd, const GpuScene& scene, VkPipelineLayout layout,
                       std::span<const InstanceDraw> draws, DrawHooks hooks = {});

}  // namespace ds::passes
