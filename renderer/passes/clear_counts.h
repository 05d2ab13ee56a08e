#pragma once
// clear_counts (clear role; count_fragments=on or zfight=on): creates and zeroes the u32 count
// images the counting passes (shadow, depth_prepass, forward, decals, transparent: their
// CountImages; zfight: res.zfight) add into, first in the frame, so the graph plans the
// transfer-to-shader dependency like any other instead of a barrier inside each counting pass.
// With count_draws it also gives each counting pass its per-draw counters (CountImages::draws):
// host buffers the host zeroes before the submit, so they need no clear.
#include "renderer/passes/frame_pass.h"
#include "renderer/settings/knob.h"

namespace ds::passes {

class ClearCountsPass final : public FramePass {
  public:
    explicit ClearCountsPass(const PassServices& services);

    const char* name() const override { return "clear_counts"; }
    static constexpr Knob<bool> kKnob{"count_fragments"};
    static std::vector<SettingDef> knobs();
    void configure(const FrameSetup& setup, FrameOptions& options) override;
    // count_fragments: on when asked for (its knob, equal_check, count_draws), on the dynamic
    // path (a subpass has no room for the count images' clears and reads); throws ds::Error
    // on a device without fragmentStoresAndAtomics.
    void resolve(FrameOptions& options) override;
    graph::PassRole role() const override { return graph::PassRole::Clear; }
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) override;
    void rebuild_pipelines(vk::DestroyList&) override {}

  private:
    void add_draw_counters(graph::RenderGraph& graph, const FrameInputs& in,
                           FrameResources& res) const;

    PassServices services_;
    bool quads_;  // the device counts quads (vk::DeviceReport::fragment_quad_operations)
};

}  // namespace ds::passes
