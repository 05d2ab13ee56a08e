// Decal classification (scene/decals.h: overlays found by geometry at load) against the
// frame: with decal_pass=off the overlays are drawn as ordinary geometry, so an OPAQUE / MASK
// overlay fights its base (DECAL_ZFIGHT, error, from the zfight pass's pairs); without the
// zfight pass to say so, the overlays that would fight are listed (DECAL_PASS_OFF, warning).
// With decal_pass=on there is nothing to report: the decals pass draws them once, after forward.
// Whatever the settings, a surface buried just behind another that faces the same way (scene/
// decals.h; a decal a compressor moved off its wall) is DECAL_BURIED, error: it never shows.
#include <cstdio>

#include "capture/diagnose/checks.h"
#include "capture/diagnose/finding_json.h"
#include "renderer/passes/decals.h"
#include "renderer/passes/zfight.h"

namespace ds::diagnose {
namespace {

constexpr const char* kDecalFix =
    "decal_pass=on: the decals pass draws classified overlays once, after forward, with a "
    "depth bias towards the camera";

// The overlay of a classified pair (a or b), as the scene's decal list names it.
bool is_overlay(const scene::Scene& scene, const SurfaceName& name) {
    for (const scene::Decal& d : scene.decals)
        if (scene.instance_name(d.instance) == name) return true;
    return false;
}

Finding decal_zfight(const CheckInput& in, const ZfightPair& pair, std::vector<uint32_t> pixels) {
    const bool a_is_overlay = is_overlay(in.scene, pair.a);
    const FindingSurface overlay = surface_named(in.scene, a_is_overlay ? pair.a : pair.b);
    const FindingSurface base = surface_named(in.scene, a_is_overlay ? pair.b : pair.a);
    Finding f;
    f.code = "DECAL_ZFIGHT";
    f.severity = Severity::Error;
    f.detector = "decals";
    f.magnitude = {double(pair.pixels), "px"};
    f.message = "decal " + label(overlay) + " fights its base " + label(base) + ": " +
                grouped(double(pair.pixels)) + " px (decal_pass=off; " + depth_label(in.settings) +
                ")";
    f.fix = kDecalFix;
    f.surfaces = {overlay, base};
    f.pointer = overlay.pointer;
    f.pixels = std::move(pixels);
    return f;
}

// decal_pass=off without the zfight pass: every OPAQUE / MASK overlay is drawn coplanar with
// its base by forward (BLEND ones go to transparent, whose closer-or-equal test is right).
void unmeasured_overlays(const CheckInput& in, CheckOutput& out) {
    Finding f;
    for (const scene::Decal& d : in.scene.decals) {
        if (in.scene.instance_material(d.instance).alpha_mode == scene::AlphaMode::Blend) continue;
        f.surfaces.push_back(surface_of(in.scene, d.instance));
    }
    if (f.surfaces.empty()) return;
    f.code = "DECAL_PASS_OFF";
    f.severity = Severity::Warning;
    f.detector = "decals";
    f.magnitude = {double(f.surfaces.size()), "overlays"};
    f.message = grouped(double(f.surfaces.size())) +
                " opaque / masked overlays are drawn as ordinary geometry, coplanar with their "
                "bases (decal_pass=off; zfight did not run to measure the fight)";
    f.fix = kDecalFix;
    f.pointer = f.surfaces.front().pointer;
    out.findings.push_back(std::move(f));
}

// "1.22 mm" below a centimetre, else "3.4 cm" or "2.5 m" (scene units read as metres).
std::string gap_text(double gap) {
    char text[32];
    if (gap < 0.01)
        std::snprintf(text, sizeof text, "%.3g mm", gap * 1000.0);
    else if (gap < 1.0)
        std::snprintf(text, sizeof text, "%.3g cm", gap * 100.0);
    else
        std::snprintf(text, sizeof text, "%.3g m", gap);
    return text;
}

// An overlay hidden just behind a surface facing the same way (scene/decals.h: buried): no
// depth setting brings it back.
void buried_overlays(const CheckInput& in, CheckOutput& out) {
    for (const scene::BuriedOverlay& b : in.scene.buried) {
        const FindingSurface overlay = surface_of(in.scene, b.instance);
        const FindingSurface base = surface_of(in.scene, b.base);
        Finding f;
        f.code = "DECAL_BURIED";
        f.severity = Severity::Error;
        f.detector = "decals";
        f.magnitude = {b.gap, "scene units"};
        f.message = label(overlay) + " lies " + gap_text(b.gap) + " behind " + label(base) +
                    ", facing the same way: hidden wherever " + label(base) +
                    " is drawn (an overlay moved off its surface, by a lossy compressor's "
                    "quantization or in modelling)";
        f.fix =
            "put it back on its surface or in front of it (export without position "
            "quantization, or with more position bits)";
        f.surfaces = {overlay, base};
        f.pointer = overlay.pointer;
        out.findings.push_back(std::move(f));
    }
}

}  // namespace

void check_decals(const CheckInput& in, CheckOutput& out) {
    buried_overlays(in, out);
    if (in.scene.decals.empty()) {
        if (in.scene.buried.empty())
            out.skip("decals",
                     "the scene has no coplanar overlays: the decal classifier found none");
        else
            out.ran.push_back("decals");
        return;
    }
    out.ran.push_back("decals");
    if (knob_value(in.settings, passes::DecalsPass::kKnob)) return;
    const ZfightResult* z = in.measured.find<ZfightResult>();
    if (!z) return unmeasured_overlays(in, out);
    std::vector<std::vector<uint32_t>> pixels = pair_pixels(*z);
    for (uint32_t i = 0; i < z->pairs.size(); ++i)
        if (is_decal_pair(in.scene, z->pairs[i].a, z->pairs[i].b))
            out.findings.push_back(decal_zfight(in, z->pairs[i], std::move(pixels[i])));
}

}  // namespace ds::diagnose
