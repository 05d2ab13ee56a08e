// DECAL (info): a coplanar overlay and the surface it lies on (the importer's classification,
// renderer/scene/decals.h: the decal pass draws it once, after forward). DECAL_WITHOUT_BASE
// (warning): an overlay that lies on nothing it could be drawn over: buried just behind a
// surface facing its way (Scene::buried: hidden wherever that surface is drawn, the way a
// lossy compressor moves a decal off its wall), or a MASK / BLEND surface named as a decal
// (node, mesh or material name holding "decal") that lies on no surface at all.
#include <algorithm>
#include <cctype>

#include "capture/diagnose/checks.h"
#include "capture/lint/checks.h"

namespace ds::lint {
namespace {

Finding decal_finding(const scene::Scene& scene, const scene::Decal& d) {
    const FindingSurface overlay = diagnose::surface_of(scene, d.instance);
    const FindingSurface base = diagnose::surface_of(scene, d.base);
    Finding f;
    f.code = "DECAL";
    f.severity = Severity::Info;
    f.detector = "decals";
    f.pointer = overlay.pointer;
    f.magnitude = {1, "surfaces"};
    f.message = "decal: " + diagnose::label(overlay) + " lies on " + diagnose::label(base) +
                " (the same plane): drawn by the decal pass after forward, not in the prepass";
    f.fix = "none needed; without the decal pass (decals=off) it would Z-fight its base";
    f.surfaces = {overlay, base};
    return f;
}

Finding buried_finding(const scene::Scene& scene, const scene::BuriedOverlay& b) {
    const FindingSurface overlay = diagnose::surface_of(scene, b.instance);
    const FindingSurface base = diagnose::surface_of(scene, b.base);
    Finding f;
    f.code = "DECAL_WITHOUT_BASE";
    f.severity = Severity::Warning;
    f.detector = "decals";
    f.pointer = overlay.pointer;
    f.magnitude = {b.gap, "scene units"};
    f.message = "overlay " + diagnose::label(overlay) + " lies " + g3(b.gap) + " behind " +
                diagnose::label(base) + ", which faces its way: hidden wherever that is drawn";
    f.fix =
        "move it onto the surface (a lossy position compression moves surfaces apart: "
        "compress positions losslessly or snap the overlay)";
    f.surfaces = {overlay, base};
    return f;
}

bool named_decal(const scene::Scene& scene, uint32_t instance) {
    const SurfaceName n = scene.instance_name(instance);
    for (std::string s : {n.node, n.mesh, n.material}) {
        std::transform(s.begin(), s.end(), s.begin(),
                       [](unsigned char c) { return std::tolower(c); });
        if (s.find("decal") != std::string::npos) return true;
    }
    return false;
}

Finding floating_finding(const scene::Scene& scene, uint32_t instance) {
    Finding f;
    f.code = "DECAL_WITHOUT_BASE";
    f.severity = Severity::Warning;
    f.detector = "decals";
    f.surfaces = {diagnose::surface_of(scene, instance)};
    f.pointer = f.surfaces.front().pointer;
    f.magnitude = {1, "surfaces"};
    f.message = diagnose::label(f.surfaces.front()) +
                " is named as a decal but lies on no surface (none within the overlay tolerance "
                "under it)";
    f.fix = "place it on the surface it decorates, with that surface's vertices where they meet";
    return f;
}

}  // namespace

void check_decals(const Input& in, Output& out) {
    out.ran.push_back("decals");
    const scene::Scene& s = in.scene;
    for (const scene::Decal& d : s.decals) out.findings.push_back(decal_finding(s, d));
    for (const scene::BuriedOverlay& b : s.buried) out.findings.push_back(buried_finding(s, b));
    std::vector<bool> overlay(s.instances.size(), false);
    for (const scene::Decal& d : s.decals) overlay.at(d.instance) = true;
    for (const scene::BuriedOverlay& b : s.buried) overlay.at(b.instance) = true;
    for (uint32_t i = 0; i < s.instances.size(); ++i)
        if (!overlay[i] && s.instance_material(i).alpha_mode != scene::AlphaMode::Opaque &&
            named_decal(s, i))
            out.findings.push_back(floating_finding(s, i));
}

}  // namespace ds::lint
