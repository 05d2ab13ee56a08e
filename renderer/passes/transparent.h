#pragma once
// transparent: BLEND materials, after the sky, one instance at a time back to front, alpha
// blended into the HDR image. Depth is tested closer-or-equal (GREATER_OR_EQUAL with
// reverse-Z) against the scene depth with writes off: decals lying exactly on a wall or the
// floor (the atrium's, Sponza's) have that surface's depth and pass, surfaces in front hide
// them, and they never hide each other. They are drawn here only (not by shadow, prepass or
// forward), so each appears exactly once (seed 004). overlay_pass.h does the rest.
//
// msaa > 1: the last pass that draws multisampled. It blends into res.msaa_hdr against
// res.msaa_depth and resolves the colour (AVERAGE) into res.hdr, which it creates, at the
// end of its rendering; forward and skybox have drawn every sample before.
// Pixel history (FrameInputs::pixel): transparent_history replays the same sorted draws first
// with the instrumented variant (pixel_history.h), reading the depth and the HDR colour there.
#include <vector>

#include "renderer/passes/overlay_pass.h"

namespace ds::passes {

class TransparentPass final : public OverlayPass {
  public:
    static constexpr const char* kName = "transparent";

    explicit TransparentPass(const PassServices& services) : OverlayPass(services, kName, true) {}

  private:
    bool runs(const FrameOptions&) const override { return true; }
    const CountImages& counts(const FrameResources& res) const override {
        return res.transparent_counts;
    }
    std::vector<Step> steps() const override { return {{.mode = std::nullopt, .blend = true}}; }
    DrawCounts draw(VkCommandBuffer cmd, const FrameInputs& in, VkPipelineLayout layout,
                    const Step& step, DrawHooks hooks) const override;
    RasterizedCount::Selection measured(const FrameInputs& in) const override;
};

}  // namespace ds::passes
