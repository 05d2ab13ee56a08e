#include "renderer/passes/transparent.h"

#include "renderer/gpu_scene/gpu_scene.h"
#include "renderer/passes/scene_draw.h"

namespace ds::passes {

// Back to front, one instance at a time.
DrawCounts TransparentPass::draw(VkCommandBuffer cmd, const FrameInputs& in,
                                 VkPipelineLayout layout, const Step&, DrawHooks hooks) const {
    const std::vector<InstanceDraw> draws =
        sort_back_to_front(*in.scene, in.camera_position, scene_groups(in.options.decal_pass));
    return draw_sorted(cmd, *in.scene, layout, draws, hooks);
}

RasterizedCount::Selection TransparentPass::measured(const FrameInputs& in) const {
    return {.samples = in.options.samples,
            .modes = {scene::AlphaMode::Blend},
            .decals = scene_groups(in.options.decal_pass)};
}

}  // namespace ds::passes
