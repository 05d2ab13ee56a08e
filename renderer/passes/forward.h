#pragma once
// The forward pass: every draw group shaded with PBR-lite into an _SRGB colour target with a
// reverse-Z depth buffer (clear 0, GREATER). Opaque groups first, then MASK groups with their
// own discard pipeline, then BLEND instances back to front with depth writes off.
#include <array>
#include <cstdint>

#include <vulkan/vulkan.h>
#include <glm/glm.hpp>

#include "renderer/scene/scene.h"
#include "renderer/vk/destroy_list.h"
#include "renderer/vk/image.h"
#include "renderer/vk/pipeline.h"

namespace ds {
class GpuScene;
namespace shader {
class Compiler;
}
namespace vk {
class Context;
}
}  // namespace ds

namespace ds::passes {

struct ForwardInputs {
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    const GpuScene* scene = nullptr;
    VkDescriptorSet frame_set = VK_NULL_HANDLE;  // set 0: frame uniforms + instances
    const vk::Image* color = nullptr;            // in COLOR_ATTACHMENT_OPTIMAL
    const vk::Image* depth = nullptr;            // in DEPTH_STENCIL_ATTACHMENT_OPTIMAL
    std::array<float, 4> clear_color{};          // linear (the attachment encodes to sRGB)
    glm::vec3 camera_position{0.0f};
};

struct ForwardStats {
    uint32_t draw_calls = 0;
    uint32_t instances = 0;
    uint32_t opaque_groups = 0;
    uint32_t mask_groups = 0;
    uint32_t blend_instances = 0;
};

class ForwardPass {
  public:
    ForwardPass(vk::Context& context, shader::Compiler& compiler, VkPipelineLayout layout,
                VkFormat color_format, VkFormat depth_format);

    // Fail-safe rebuild: every shader variant compiles first (throws shader::ShaderError and
    // keeps the current pipelines); only then are the pipelines replaced, the old ones going
    // to `retired` because an in-flight frame may still use them.
    void rebuild_pipelines(vk::DestroyList& retired);

    ForwardStats record(const ForwardInputs& in) const;

    static constexpr const char* kVertexShader = "forward.vert";
    static constexpr const char* kFragmentShader = "forward.frag";

  private:
    void draw_groups(const ForwardInputs& in, VkPipeline pipeline, scene::AlphaMode alpha_mode,
                     ForwardStats& stats) const;
    void draw_blended(const ForwardInputs& in, ForwardStats& stats) const;

    vk::Context& context_;
    shader::Compiler& compiler_;
    VkPipelineLayout layout_;
    VkFormat color_format_;
    VkFormat depth_format_;
    vk::Pipeline opaque_;
    vk::Pipeline mask_;
    vk::Pipeline blend_;
};

}  // namespace ds::passes
