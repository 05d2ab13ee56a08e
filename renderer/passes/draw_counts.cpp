#include "renderer/passes/draw_counts.h"

#include <cstring>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/common/error.h"
#include "renderer/common/surface_json.h"
#include "renderer/gpu_scene/gpu_scene.h"
#include "renderer/readback/host_readback.h"
#include "renderer/vk/capabilities.h"

namespace ds::passes {
namespace {

const char* alpha_mode_name(scene::AlphaMode mode) {
    switch (mode) {
        case scene::AlphaMode::Opaque:
            return "opaque";
        case scene::AlphaMode::Mask:
            return "mask";
        case scene::AlphaMode::Blend:
            break;
    }
    return "blend";
}

// Per pixel, the draw group whose surface won + 1 (0: none), and the histogram per group.
void histogram(std::span<const std::byte> ids, const GpuScene& scene, DrawsResult& frame,
               std::vector<uint64_t>& visible) {
    const SurfaceTable& table = scene.surfaces();
    const std::vector<uint32_t>& groups = scene.instance_groups();
    frame.draw_pixels.assign(ids.size() / sizeof(uint32_t), 0);
    uint32_t last_id = 0, last_group = 0;  // neighbouring pixels mostly share a surface
    for (size_t i = 0; i < frame.draw_pixels.size(); ++i) {
        uint32_t id;
        std::memcpy(&id, ids.data() + i * sizeof id, sizeof id);
        if (id == 0) continue;
        if (id != last_id) {
            const std::optional<SurfaceRef> ref = table.find(id);
            if (!ref) continue;  // cannot happen for ids the prepass wrote
            last_id = id;
            last_group = groups.at(ref->instance) + 1;
        }
        frame.draw_pixels[i] = last_group;
        ++visible.at(last_group - 1);
    }
}

// The draw's counts from the passes that measured it.
void fill_counts(DrawReport& d, std::span<const PassResult> passes,
                 const std::vector<uint64_t>* visible) {
    for (const PassResult& p : passes) {
        if (d.group < p.draw_samples_passed.size())
            d.samples_passed = p.draw_samples_passed[d.group];
    }
    // A group the visibility pass does not draw (BLEND, decals) has no surface_id of its own.
    if (visible && d.samples_passed) d.visible_pixels = (*visible)[d.group];
    for (const PassResult& p : passes) {
        if (d.group >= p.draw_shaded.size()) continue;
        const uint64_t shaded = p.draw_shaded[d.group];
        d.shaded_fragments.emplace_back(p.name, shaded);
        // Waste where the pass shaded the draw at all: a pass that does not draw it (BLEND's
        // transparent for an opaque group) is no saving either.
        if (d.visible_pixels && p.draw_shaded_in_view && shaded > 0)
            d.wasted_fragments.emplace_back(p.name, int64_t(shaded) - int64_t(*d.visible_pixels));
    }
    if (d.visible_pixels)
        d.occluded = *d.visible_pixels == 0;
    else if (d.samples_passed)
        d.occluded = *d.samples_passed == 0;
}

// One entry per scene draw group; a count that was not measured is null, never 0.
nlohmann::json draws_json(const std::vector<DrawReport>& draws) {
    nlohmann::json out = nlohmann::json::array();
    for (const DrawReport& d : draws) {
        nlohmann::json entry = surface_json(d.name);  // node: the group's first instance's
        entry["group"] = d.group;
        entry["instances"] = {d.first_instance, d.instances};
        entry["alpha_mode"] = d.alpha_mode;
        if (d.decal) entry["decal"] = true;
        entry["visible_pixels"] = d.visible_pixels ? nlohmann::json(*d.visible_pixels) : nullptr;
        entry["samples_passed"] = d.samples_passed ? nlohmann::json(*d.samples_passed) : nullptr;
        nlohmann::json shaded = nlohmann::json::object(), wasted = nlohmann::json::object();
        for (const auto& [pass, n] : d.shaded_fragments) shaded[pass] = n;
        for (const auto& [pass, n] : d.wasted_fragments) wasted[pass] = n;
        entry["shaded_fragments"] = std::move(shaded);
        entry["wasted_fragments"] = std::move(wasted);
        entry["occluded"] = d.occluded;
        if (d.hiz) {
            entry["hiz"] = hiz_verdict_name(*d.hiz);
            entry["hiz_occluded_instances"] = d.hiz_occluded_instances;
            entry["hiz_unsafe"] = d.hiz_unsafe;
        }
        out.push_back(std::move(entry));
    }
    return out;
}

}  // namespace

std::vector<SettingDef> DrawCountsPass::knobs() {
    return {bool_knob(kKnob, "measurement", false,
                      "per draw group: visible pixels (from surface_id), samples passed (a "
                      "precise occlusion query per draw in the prepass, or forward without it) "
                      "and shaded fragments per counting pass (report draws, Draws panel; turns "
                      "on count_fragments and surface_id)",
                      Invalidates::Pipelines)};
}

void DrawCountsPass::configure(const FrameSetup& setup, FrameOptions& o) {
    const bool knob = knob_value(setup.settings, kKnob);
    o.count_draws = knob && !o.subpass;
    if (knob && o.subpass) set_turned_off(kKnob.name);
    if (!o.count_draws) return;
    o.requests.counts = o.requests.surface_id = true;
    if (!setup.device.occlusion_query_precise)
        throw Error("count_draws=on needs occlusionQueryPrecise, which " +
                    setup.device.candidate.name + " does not offer");
}

void DrawCountsPass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    if (!in.options.count_draws || !res.surface_id.valid()) return;
    services_.readback.add_copy_pass(graph, name(), {res.surface_id});
}

void DrawCountsPass::collect(const FrameCollect& c, std::span<PassResult>, FrameResult& frame) {
    if (!c.in.options.count_draws) return;
    const GpuScene& scene = *c.in.scene;
    const std::vector<scene::DrawGroup>& groups = scene.draw_groups();
    std::vector<uint64_t> visible(groups.size(), 0);
    const std::span<const std::byte> ids = c.res.surface_id.valid()
                                               ? c.readback.image_bytes(c.res.surface_id)
                                               : std::span<const std::byte>{};
    DrawsResult r;
    if (!ids.empty()) histogram(ids, scene, r, visible);
    if (!c.in.options.prepass)
        r.visible_note = "prepass=off: visible pixels come from the prepass's surface_id";
    else if (c.in.options.msaa())
        r.visible_note = "msaa > 1: visible pixels are sample 0's winner";
    for (const PassResult& p : frame.passes)
        if (!p.draw_samples_passed.empty()) r.samples_pass = p.name;
    for (size_t g = 0; g < groups.size(); ++g) {
        const scene::DrawGroup& group = groups[g];
        DrawReport d;
        d.group = uint32_t(g);
        d.first_instance = group.first_instance;
        d.instances = group.instance_count;
        d.alpha_mode = alpha_mode_name(group.alpha_mode);
        d.decal = group.decal;
        if (group.instance_count > 0) d.name = scene.surfaces().name(group.first_instance);
        fill_counts(d, frame.passes, ids.empty() ? nullptr : &visible);
        r.draws.push_back(std::move(d));
    }
    frame.slots.put(std::move(r), &draws_report);
}

// count_draws=on: report.json's "draws" and "draws_info".
void draws_report(const DrawsResult& r, const FrameResult&, nlohmann::json& report) {
    if (r.draws.empty()) return;
    report["draws"] = draws_json(r.draws);
    report["draws_info"] = {
        {"samples_passed_from", r.samples_pass},
        {"visible_pixels",
         r.visible_note.empty() ? "surface_id (the prepass's winner)" : r.visible_note}};
}

const DrawsResult& draws_of(const FrameResult& frame) {
    static const DrawsResult none;
    const DrawsResult* r = frame.find<DrawsResult>();
    return r ? *r : none;
}

}  // namespace ds::passes
