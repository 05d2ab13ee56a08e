// From the fragment and per-draw counts (count_fragments, count_draws: passes/draw_counts.h),
// wasted work per draw (warnings):
// - OCCLUDED_DRAW: drawn by the visibility pass and nothing of it shows (visible pixels 0, or
//   without the prepass no sample passed), yet it was drawn (magnitude: what it shaded in the
//   passes drawn from the camera); overlays are left to check_decals;
// - WASTED_FRAGMENTS: a draw that in some in-view pass shaded more fragments that do not show
//   than pixels that do, and at least 1 % of the covered pixels (the five largest).
#include <algorithm>

#include "capture/diagnose/checks.h"
#include "capture/diagnose/finding_json.h"
#include "renderer/passes/draw_counts.h"

namespace ds::diagnose {
namespace {

constexpr size_t kMaxWastedDraws = 5;
constexpr double kWastedShareOfCovered = 0.01;
constexpr size_t kMaxSurfaces = 10;  // instances named per draw

// What the draw shaded in the passes drawn from the camera (not the light's shadow map).
uint64_t shaded_in_view(const FrameResult& frame, const DrawReport& d) {
    uint64_t n = 0;
    for (const auto& [pass, count] : d.shaded_fragments) {
        const PassResult* p = pass_named(frame, pass);
        if (p && p->draw_shaded_in_view) n += count;
    }
    return n;
}

Finding occluded_finding(const CheckInput& in, const DrawReport& d) {
    Finding f;
    f.code = "OCCLUDED_DRAW";
    f.severity = Severity::Warning;
    f.detector = "draws";
    f.magnitude = {double(shaded_in_view(in.measured, d)), "fragments"};
    f.message = "occluded draw: " + group_label(in.scene, d.first_instance, d.instances) +
                " shows no pixel and shades " + grouped(f.magnitude.value) + " fragments";
    f.fix =
        "cull it before drawing (an occlusion or Hi-Z test: hiz=on shows what one would "
        "cull), or leave it out of this view";
    f.surfaces = group_surfaces(in.scene, d.first_instance, d.instances, kMaxSurfaces);
    f.pointer = f.surfaces.front().pointer;
    return f;
}

struct Waste {
    const DrawReport* draw = nullptr;
    std::string pass;
    int64_t wasted = 0;
};

Finding wasted_finding(const CheckInput& in, const DrawsResult& draws, const Waste& w) {
    Finding f;
    f.code = "WASTED_FRAGMENTS";
    f.severity = Severity::Warning;
    f.detector = "draws";
    f.magnitude = {double(w.wasted), "fragments"};
    f.message = w.pass + " shades " + grouped(double(w.wasted)) + " fragments of " +
                group_label(in.scene, w.draw->first_instance, w.draw->instances) +
                " that do not show (" + grouped(double(w.draw->visible_pixels.value_or(0))) +
                " visible px)";
    f.fix = w.draw->alpha_mode == "mask"
                ? "alpha-tested: its shader runs before the depth test; draw it after opaque "
                  "and keep its cut-outs tight"
                : "draw it front to back (prepass_sort=on) or behind fewer occluders";
    f.surfaces = group_surfaces(in.scene, w.draw->first_instance, w.draw->instances, kMaxSurfaces);
    f.pointer = f.surfaces.front().pointer;
    for (uint32_t i = 0; i < draws.draw_pixels.size(); ++i)
        if (draws.draw_pixels[i] == w.draw->group + 1) f.pixels.push_back(i);
    return f;
}

void wasted_draws(const CheckInput& in, const DrawsResult& draws, CheckOutput& out) {
    const double covered = double(in.measured.covered_pixels.value_or(0));
    std::vector<Waste> waste;
    for (const DrawReport& d : draws.draws) {
        if (d.occluded || !d.visible_pixels) continue;
        Waste most{&d, "", 0};
        for (const auto& [pass, n] : d.wasted_fragments)
            if (n > most.wasted) most = {&d, pass, n};
        if (most.wasted > int64_t(*d.visible_pixels) &&
            double(most.wasted) >= kWastedShareOfCovered * covered)
            waste.push_back(most);
    }
    std::stable_sort(waste.begin(), waste.end(),
                     [](const Waste& a, const Waste& b) { return a.wasted > b.wasted; });
    for (size_t i = 0; i < waste.size() && i < kMaxWastedDraws; ++i)
        out.findings.push_back(wasted_finding(in, draws, waste[i]));
}

}  // namespace

void check_draws(const CheckInput& in, CheckOutput& out) {
    const DrawsResult* draws = in.measured.find<DrawsResult>();
    if (!draws) {
        out.skip("draws", frame_skip_reason(in.measured, "readback_draws", "count_draws")
                              .value_or("count_draws did not run"));
        return;
    }
    out.ran.push_back("draws");
    // Overlays: whether they show is check_decals' (with decal_pass=off their base wins the
    // prepass wherever they fight it, so they read as occluded).
    for (const DrawReport& d : draws->draws)
        if (d.occluded && !d.decal) out.findings.push_back(occluded_finding(in, d));
    wasted_draws(in, *draws, out);
}

}  // namespace ds::diagnose
