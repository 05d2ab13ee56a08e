#pragma once
// Set 2 of the passes that light scene surfaces, forward and transparent
// (shaders/common/lighting.glsl): the shadow map, the prepass normal and roughness, AO and
// contact shadows. An input the frame does not have is bound to a 1x1 fallback (white; a
// shadow map that lights everything), so one layout serves every combination of settings.
#include <cstdint>

#include <vulkan/vulkan.h>

#include "renderer/graph/graph.h"
#include "renderer/passes/pass_util.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/image.h"

namespace ds::vk {
class Context;
}

namespace ds::passes {

struct LightingInputs {
    graph::ImageHandle shadow_map;
    graph::ImageHandle normals;    // prepass; forward only
    graph::ImageHandle roughness;  // prepass; forward only
    graph::ImageHandle ao;
    graph::ImageHandle contact_shadows;
};

class LightingSet {
  public:
    LightingSet(vk::Context& context, VkFormat shadow_format);

    VkDescriptorSetLayout layout() const { return layout_.handle(); }
    // Declares a fragment-shader sampled read of every valid input.
    static void declare(graph::PassBuilder& builder, const LightingInputs& in);
    // This frame's set, from the images the graph gave the inputs.
    VkDescriptorSet write(const graph::PassContext& ctx, uint64_t frame_number,
                          const LightingInputs& in);

  private:
    void create_fallbacks(VkFormat shadow_format);

    vk::Context& context_;
    vk::DescriptorSetLayout layout_;
    FrameDescriptorPool pool_;
    vk::Sampler shadow_sampler_;  // compare LESS_OR_EQUAL, border: lit
    vk::Sampler linear_;          // screen-space inputs of another resolution
    vk::Sampler nearest_;         // texelFetch needs none, but a combined sampler needs one
    vk::Image white_;
    vk::Image lit_shadow_;  // depth 1.0: every reference passes
};

}  // namespace ds::passes
