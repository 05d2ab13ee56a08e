#include "renderer/passes/decals.h"

#include "renderer/gpu_scene/gpu_scene.h"
#include "renderer/passes/scene_draw.h"

namespace ds::passes {

using scene::AlphaMode;

namespace {

// Towards the camera: 4 steps of the depth format plus one pixel's depth slope.
constexpr float kBiasSteps = 4.0f;
constexpr float kBiasSlope = 1.0f;

}  // namespace

std::vector<SettingDef> DecalsPass::knobs() {
    return {bool_knob(kKnob, "passes", true,
                      "coplanar overlays (classified at load: triangles lying on another surface "
                      "and inside it) skip shadow, prepass and forward and are drawn once by the "
                      "decals pass after forward; off: drawn like any surface (they Z-fight)",
                      Invalidates::Nothing)};
}

// The other geometry passes leave decal groups to this one when it runs (scene_groups).
void DecalsPass::configure(const FrameSetup& setup, FrameOptions& o) {
    o.decal_pass = knob_value(setup.settings, kKnob) && setup.scene.decal_groups() > 0;
}

// Opaque, MASK, BLEND overlays.
std::vector<OverlayPass::Step> DecalsPass::steps() const {
    return {{AlphaMode::Opaque, false, kBiasSteps, kBiasSlope},
            {AlphaMode::Mask, false, kBiasSteps, kBiasSlope},
            {AlphaMode::Blend, true, kBiasSteps, kBiasSlope}};
}

// The step's overlays in authored order.
DrawCounts DecalsPass::draw(VkCommandBuffer cmd, const FrameInputs& in, VkPipelineLayout layout,
                            const Step& step, DrawHooks hooks) const {
    const AlphaMode mode = *step.mode;
    return draw_groups(cmd, *in.scene, layout, {&mode, 1}, Decals::Only, std::nullopt, hooks);
}

RasterizedCount::Selection DecalsPass::measured(const FrameInputs& in) const {
    return {.samples = in.options.samples,
            .modes = {AlphaMode::Opaque, AlphaMode::Mask, AlphaMode::Blend},
            .decals = Decals::Only};
}

}  // namespace ds::passes
