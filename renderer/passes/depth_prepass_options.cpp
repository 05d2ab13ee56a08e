#include "renderer/passes/depth_prepass.h"

// The prepass's knobs, its options for a frame and the surface ids it provides to others.
#include <nlohmann/json.hpp>

#include "renderer/common/error.h"
#include "renderer/vk/capabilities.h"
#include "renderer/vk/context.h"

namespace ds::passes {

std::vector<SettingDef> DepthPrepass::knobs() {
    using I = Invalidates;
    return {
        bool_knob(kMaskedSplit, "prepass and depth", true,
                  "separate prepass pipeline for MASK materials; off: one pipeline with discard "
                  "for all geometry (loses early-Z)",
                  I::Nothing),
        bool_knob(kPrepassSort, "prepass and depth", true,
                  "prepass draws opaque and masked instances front to back (prepass_mode=depth: "
                  "whole instanced groups, by their nearest instance; off: instanced groups in "
                  "the scene's authored order, every hidden layer shaded)",
                  I::Nothing),
        bool_knob(kCountDiscards, "measurement", false,
                  "count fragments the masked prepass pipeline ran and discarded "
                  "(masked_discards in the report)",
                  I::Pipelines),
        bool_knob(kSurfaceId, "diagnostics", false,
                  "the prepass also writes surface_id: per pixel, the surface (triangle of an "
                  "instance) that won the depth test (on whenever zfight is)",
                  I::Pipelines),
        bool_knob(kAlphaMip, "diagnostics", false,
                  "the prepass also writes image alpha_mip: per pixel, the mip level of the base "
                  "colour that the winning MASK surface's alpha test sampled (textureQueryLod; 0 "
                  "with alpha_level0), -1 on every other pixel; msaa > 1: the samples averaged; "
                  "not on render_path=subpass",
                  I::Pipelines),
    };
}

void DepthPrepass::configure(const FrameSetup& setup, FrameOptions& o) {
    const Settings& s = setup.settings;
    masked_split_ = knob_value(s, kMaskedSplit);
    prepass_sort_ = knob_value(s, kPrepassSort);
    // The discard counters are storage writes that a render pass's subpass has no room for.
    const bool discards = knob_value(s, kCountDiscards);
    count_discards_ = discards && !o.subpass;
    const bool surface_id = knob_value(s, kSurfaceId);
    if (surface_id) o.requests.surface_id = true;
    if (!o.prepass) set_skipped("prepass=off");
    if (o.subpass && surface_id) set_turned_off(kSurfaceId.name);
    if (o.subpass && discards) set_turned_off(kCountDiscards.name);
    // One more colour attachment, which the subpass path's render pass does not have.
    const bool alpha_mip = knob_value(s, kAlphaMip);
    alpha_mip_ = alpha_mip && o.prepass && !o.subpass;
    if (o.subpass && alpha_mip) set_turned_off(kAlphaMip.name);
}

// The prepass writes surface ids from gl_PrimitiveID in its fragment shader, which Vulkan
// allows only on devices with geometryShader.
void DepthPrepass::resolve(FrameOptions& o) {
    o.surface_id = o.requests.surface_id && o.prepass && !o.subpass;
    const vk::DeviceReport& device = services_.context.report();
    if (o.surface_id && !device.geometry_shader)
        throw Error(
            "surface ids (surface_id, zfight, equal_check, count_draws) need the "
            "geometryShader feature, which " +
            device.candidate.name + " does not offer");
}

void discards_report(const DiscardCounts& d, const FrameResult&, nlohmann::json& report) {
    report["masked_discards"] = {{"invoked", d.invoked}, {"discarded", d.discarded}};
}

}  // namespace ds::passes
