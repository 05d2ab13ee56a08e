#include "renderer/passes/contact_shadows.h"

#include <string>

#include "renderer/passes/pass_util.h"

namespace ds::passes {

using graph::Access;

ContactShadowsPass::ContactShadowsPass(const PassServices& services, uint32_t steps)
    : kernel_(services, kShader,
              {KernelBinding::Sampled, KernelBinding::Sampled, KernelBinding::Storage},
              sizeof(Params)),
      steps_(steps) {
    vk::DestroyList nothing_in_flight;
    rebuild_pipelines(nothing_in_flight);
}

void ContactShadowsPass::rebuild_pipelines(vk::DestroyList& retired) {
    kernel_.rebuild(retired, {{"STEPS", std::to_string(steps_)}});
}

std::vector<SettingDef> ContactShadowsPass::knobs() {
    return {bool_knob(kKnob, "passes", true, "screen-space march toward the sun",
                      Invalidates::Nothing)};
}

// It marches the prepass depth: no prepass, no effect; nothing runs between the subpasses.
void ContactShadowsPass::configure(const FrameSetup& setup, FrameOptions& o) {
    const bool knob = knob_value(setup.settings, kKnob);
    o.contact_shadows = knob && o.prepass && !o.subpass;
    if (!o.contact_shadows) set_skipped(off_or_without_prepass(knob, o, kKnob.name));
    if (knob && o.subpass) set_turned_off(kKnob.name);
}

void ContactShadowsPass::add(graph::RenderGraph& graph, const FrameInputs& in,
                             FrameResources& res) {
    if (!in.options.contact_shadows) return;
    const graph::ImageDesc desc{.format = kFormat,
                                .size = graph::ImageSize::relative(1.0f),
                                .semantic = graph::Semantic::UnormScalar};
    res.contact_shadows = add_depth_normals_pass(graph, "contact_shadows", "contact_shadows", desc,
                                                 kernel_, &params_, in, res);
}

}  // namespace ds::passes
