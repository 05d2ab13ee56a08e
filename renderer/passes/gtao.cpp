#include "renderer/passes/gtao.h"

#include <string>

#include "renderer/common/error.h"
#include "renderer/passes/pass_util.h"

namespace ds::passes {

using graph::Access;

GtaoPass::GtaoPass(const PassServices& services, float resolution_scale, uint32_t slices,
                   uint32_t steps)
    : kernel_(services, kShader,
              {KernelBinding::Sampled, KernelBinding::Sampled, KernelBinding::Storage},
              sizeof(Params)),
      scale_(resolution_scale),
      slices_(slices),
      steps_(steps) {
    if (!(scale_ > 0.0f && scale_ <= 1.0f))
        throw Error("gtao: resolution scale " + std::to_string(scale_) + " is not in (0, 1]");
    vk::DestroyList nothing_in_flight;
    rebuild_pipelines(nothing_in_flight);
}

void GtaoPass::rebuild_pipelines(vk::DestroyList& retired) {
    kernel_.rebuild(retired,
                    {{"SLICES", std::to_string(slices_)}, {"STEPS", std::to_string(steps_)}});
}

std::vector<SettingDef> GtaoPass::knobs() {
    return {bool_knob(kKnob, "passes", true, "ground-truth AO from prepass depth and normals",
                      Invalidates::Nothing)};
}

// GTAO reads the prepass depth (and normals): no prepass, no effect; and nothing may run
// between the subpasses. ao_spatial and ao_temporal follow it (FrameOptions::gtao_skipped).
void GtaoPass::configure(const FrameSetup& setup, FrameOptions& o) {
    const bool knob = knob_value(setup.settings, kKnob);
    o.gtao = knob && o.prepass && !o.subpass;
    o.gtao_skipped.reset();
    if (!o.gtao) {
        o.gtao_skipped = off_or_without_prepass(knob, o, kKnob.name);
        set_skipped(*o.gtao_skipped);
    }
    if (knob && o.subpass) set_turned_off(kKnob.name);
}

void GtaoPass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    if (!in.options.gtao) return;
    const graph::ImageDesc desc{.format = kFormat,
                                .size = graph::ImageSize::relative(scale_),
                                .semantic = graph::Semantic::AO};
    res.ao_raw = add_depth_normals_pass(graph, "gtao", "ao_raw", desc, kernel_, &params_, in, res);
}

}  // namespace ds::passes
