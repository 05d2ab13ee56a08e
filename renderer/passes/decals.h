#pragma once
// decals (decal_pass=on and the scene has coplanar overlays): seed 004's fix. The overlays the
// importer classified (scene::DrawGroup::decal: triangles lying on another surface and inside
// it) skip shadow, prepass, forward, zfight and transparent, and are drawn here once, after
// forward: opaque overlays first, then MASK (alpha tested), then BLEND (alpha blended), each
// in authored order. Depth is tested closer-or-equal against the scene depth with writes off
// and a small bias towards the camera (4 steps plus one pixel's depth slope), so an overlay
// with its base's exact vertices passes where the base won, one with its own vertices inside
// the base's triangles passes despite rounding, and surfaces in front still hide both. Lit
// like transparent (shaders/transparent.frag with ALPHA_MODE), with the overlay's own normal
// and the base's AO and contact shadows (overlay_pass.h).
//
// msaa > 1: draws into res.msaa_hdr against res.msaa_depth; transparent resolves afterwards.
// Pixel history (FrameInputs::pixel): decals_history replays the three steps first with the
// instrumented variants (pixel_history.h). The replay has no depth attachment, so its depths
// carry no bias: the simulated test compares the unbiased depth with the scene depth.
#include <vector>

#include "renderer/passes/overlay_pass.h"
#include "renderer/settings/knob.h"

namespace ds::passes {

class DecalsPass final : public OverlayPass {
  public:
    static constexpr const char* kName = "decals";

    explicit DecalsPass(const PassServices& services) : OverlayPass(services, kName, false) {}

    static constexpr Knob<bool> kKnob{"decal_pass"};
    static std::vector<SettingDef> knobs();
    void configure(const FrameSetup& setup, FrameOptions& options) override;

  private:
    bool runs(const FrameOptions& o) const override { return o.decal_pass; }
    const CountImages& counts(const FrameResources& res) const override { return res.decal_counts; }
    std::vector<Step> steps() const override;
    DrawCounts draw(VkCommandBuffer cmd, const FrameInputs& in, VkPipelineLayout layout,
                    const Step& step, DrawHooks hooks) const override;
    RasterizedCount::Selection measured(const FrameInputs& in) const override;
};

}  // namespace ds::passes
