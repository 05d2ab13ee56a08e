#pragma once
// Filling passes::FrameUniforms for one frame: camera projections in the frame's depth
// convention, the sun (direction from the settings, shadow projection fitted to the scene),
// ambient, exposure, alpha cutoff and the kFrame* flags.
#include <cstdint>

#include <vulkan/vulkan.h>
#include <glm/glm.hpp>

#include "renderer/passes/frame.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings.h"

namespace ds {

// Right-handed perspective for Vulkan clip space with y flipped (row 0 of the image is the
// top; counter-clockwise triangles stay front-facing). Reverse-Z maps near to 1 and far to 0;
// otherwise near 0, far 1.
glm::mat4 perspective(float yfov, float aspect, float znear, float zfar, bool reverse_z);

struct UniformInputs {
    const scene::Camera& camera;
    const Settings& settings;
    const passes::FrameOptions& options;
    const scene::DirectionalLight& sun;  // the scene's; the settings may override it
    const scene::Bounds& scene_bounds;   // the shadow projection covers them
    VkExtent2D size;
    const glm::mat4* previous_view_projection;  // null: a cut (use this frame's)
    uint32_t flags = 0;                         // kFrame* bits the renderer decided
    uint64_t frame_number = 0;
};

passes::FrameUniforms frame_uniforms(const UniformInputs& in);

}  // namespace ds
