#pragma once
// readback_draws (read-back role; count_draws=on): copies the prepass's surface_id to the host
// and, after the fence, assembles a DrawsResult — one DrawReport per scene draw group —
// from what the passes measured: visible pixels, a histogram of surface_id (surface ->
// instance -> group, gpu_scene SurfaceTable and instance_groups); samples passed, from the
// pass whose PassResult carries occlusion queries per draw (the prepass, else forward);
// shaded fragments per pass, from every PassResult with per-draw counts (whatever pass binds
// the count set with count_draws). It names no pass: listed after every pass it reads.
#include <nlohmann/json_fwd.hpp>

#include "renderer/common/surface_name.h"
#include "renderer/passes/frame_pass.h"
#include "renderer/passes/hiz_verdict.h"
#include "renderer/settings/knob.h"

namespace ds {

// count_draws=on: one scene draw group (mesh + instance range, what forward draws in one
// call; the sorted prepass draws its instances one by one) and what each pass did with it.
struct DrawReport {
    uint32_t group = 0;  // index in the scene's draw groups
    SurfaceName name;    // mesh, material, and the node of its first instance
    uint32_t first_instance = 0, instances = 0;
    std::string alpha_mode;  // "opaque" | "mask" | "blend"
    bool decal = false;      // a coplanar overlay (drawn by the decals pass when it runs)
    // Pixels whose surface_id (the prepass's winner) is one of its instances' triangles: they
    // sum to covered_pixels (msaa > 1: sample 0's winner). None without the prepass, and for
    // a group the prepass does not draw (BLEND, decals).
    std::optional<uint64_t> visible_pixels;
    // Samples that passed the visibility pass's depth test; none where it does not draw it.
    std::optional<uint64_t> samples_passed;
    // Per counting pass (by pass name): fragments that ran its fragment shader.
    std::vector<std::pair<std::string, uint64_t>> shaded_fragments;
    // Per in-view counting pass that shaded it (> 0), where visible_pixels is known: shaded
    // minus visible, the fragments that ran its shader and do not show.
    std::vector<std::pair<std::string, int64_t>> wasted_fragments;
    // Drawn by the visibility pass and nothing of it visible (visible_pixels, or without the
    // prepass samples_passed, is 0).
    bool occluded = false;
    // hiz=on: the Hi-Z test's verdict, how many of its instances it found occluded, and
    // whether it disagrees unsafely with samples_passed (not visible, yet samples passed).
    std::optional<HizVerdict> hiz;
    uint32_t hiz_occluded_instances = 0;
    bool hiz_unsafe = false;
};

// count_draws=on: every scene draw group, in scene order; the pass whose occlusion queries
// gave samples_passed; why visible pixels are missing ("" when they are not); per pixel
// (row 0 = top), the draw group whose surface won + 1 (0: none; empty without the prepass):
// what the viewer highlights for a selected draw.
struct DrawsResult {
    std::vector<DrawReport> draws = {};
    std::string samples_pass = {};
    std::string visible_note = {};
    std::vector<uint32_t> draw_pixels = {};
};

}  // namespace ds

namespace ds::passes {

// Its report.json section(s), put with the result (ResultSlots).
// The frame's DrawsResult; an empty one when count_draws did not run.
const DrawsResult& draws_of(const FrameResult& frame);

void draws_report(const DrawsResult& result, const FrameResult& frame, nlohmann::json& report);

class DrawCountsPass final : public FramePass {
  public:
    explicit DrawCountsPass(const PassServices& services) : services_(services) {}

    const char* name() const override { return "readback_draws"; }
    static constexpr Knob<bool> kKnob{"count_draws"};
    static std::vector<SettingDef> knobs();
    // count_draws: per-draw counts (count_fragments) named by surface_id, and occlusion
    // queries; throws ds::Error on a device without occlusionQueryPrecise.
    void configure(const FrameSetup& setup, FrameOptions& options) override;
    graph::PassRole role() const override { return graph::PassRole::ReadBack; }
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) override;
    void rebuild_pipelines(vk::DestroyList&) override {}  // a copy has no pipeline
    void collect(const FrameCollect& c, std::span<PassResult> own, FrameResult& frame) override;

  private:
    PassServices services_;
};

}  // namespace ds::passes
