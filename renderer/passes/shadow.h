#pragma once
// shadow: the sun's shadow map, first in the frame. A fixed-size D32 image rendered with an
// orthographic projection along the sun that fit_sun() fits around the scene bounds; depth
// runs 0 (towards the sun) to 1 with LESS, whatever the scene's depth convention. Cull none:
// single-sided walls still cast shadows from behind. Opaque groups use a depth-only pipeline,
// MASK groups an alpha-tested one after them. Forward and transparent sample it with PCF
// (shaders/common/lighting.glsl).
#include <cstdint>

#include <vulkan/vulkan.h>
#include <glm/glm.hpp>

#include "renderer/graph/graph.h"
#include "renderer/passes/frame.h"
#include "renderer/passes/pass_util.h"
#include "renderer/scene/scene.h"
#include "renderer/vk/destroy_list.h"
#include "renderer/vk/pipeline.h"

namespace ds::passes {

class ShadowPass {
  public:
    static constexpr const char* kName = "shadow";
    // 2048^2 costs lavapipe a few ms at most (the atrium: ~40 m across, 2 cm texels).
    static constexpr uint32_t kSize = 2048;

    explicit ShadowPass(const PassServices& services);

    // Fail-safe: all stages compile first; on an error the current pipelines stay.
    void rebuild_pipelines(vk::DestroyList& retired);
    // Creates res.shadow_map and draws into it.
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res);

    // World -> shadow clip space: looking along -to_sun, x/y/depth spanning the bounds
    // (a little padded), depth 0 nearest the sun.
    static glm::mat4 fit_sun(const scene::Bounds& bounds, glm::vec3 to_sun);

  private:
    enum Variant : uint32_t { kOpaque = 0, kMask = 1 };
    ShaderStages compile(uint32_t key) const;
    vk::Pipeline create(uint32_t key, const ShaderStages& stages) const;
    void record(VkCommandBuffer cmd, VkImageView map, const FrameInputs& in, VkPipeline opaque,
                VkPipeline mask) const;

    PassServices services_;
    vk::PipelineLayout layout_;
    PipelineVariants pipelines_;
};

}  // namespace ds::passes
