#pragma once
// readback_draws (read-back role; count_draws=on): copies the prepass's surface_id to the host
// and, after the fence, assembles FrameResult::draws — one DrawReport per scene draw group —
// from what the passes measured: visible pixels, a histogram of surface_id (surface ->
// instance -> group, gpu_scene SurfaceTable and instance_groups); samples passed, from the
// pass whose PassResult carries occlusion queries per draw (the prepass, else forward);
// shaded fragments per pass, from every PassResult with per-draw counts (whatever pass binds
// the count set with count_draws). It names no pass: listed after every pass it reads.
#include "renderer/passes/frame_pass.h"

namespace ds::passes {

class DrawCountsPass final : public FramePass {
  public:
    explicit DrawCountsPass(const PassServices& services) : services_(services) {}

    const char* name() const override { return "readback_draws"; }
    graph::PassRole role() const override { return graph::PassRole::ReadBack; }
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) override;
    void rebuild_pipelines(vk::DestroyList&) override {}  // a copy has no pipeline
    void collect(const FrameCollect& c, std::span<PassResult> own, FrameResult& frame) override;

  private:
    PassServices services_;
};

}  // namespace ds::passes
