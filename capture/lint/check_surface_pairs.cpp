// Surfaces of two instances that share depth (renderer/scene/surface_pairs.h finds them):
// - DUPLICATE_INSTANCE (error): the same triangles twice (the same mesh under equal
//   transforms, or a copy): they Z-fight everywhere; it replaces COPLANAR_OVERLAP for the pair.
// - COPLANAR_OVERLAP (error): same-facing surfaces overlapping within the decal classifier's
//   epsilon where neither is a decal of the other (Scene::decals: an overlay and its base, or
//   two overlays of one base, are drawn by the decal pass and do not fight).
// - NEAR_COPLANAR_FIGHT: parallel, same-facing, overlapping surfaces whose least gap along the
//   normal is more than epsilon yet below one depth step somewhere between the first view's
//   planes, up to the scene's farthest corner from that view (checks.h seen_to). Seen head-on
//   from beyond the fight distance (lint_depth.cpp's fight_distance) they
//   store the same depth: a warning when that happens in the user's depth format, with the
//   distance; information when only in other formats. Every format's distance is in the
//   message and in the finding's values. Surfaces are looked for up to the coarsest step of
//   the user's format, d32f reverse-Z, d32f forward-Z and d24 (d16 only when chosen: its steps
//   would pair nearly every parallel surface of a large scene).
// Coplanar and near pairs inside a closed solid are left out: end caps of beams inside a wall,
// the bases of engaged columns. From the pair's largest overlap, lifted just off both surfaces
// along the side they face (kLift, relative to the point's magnitude like the decal
// classifier's epsilon), a ray along that side meets a back face first: it starts inside a
// solid, so nothing can look at the overlap. A double-sided pair must be enclosed on both
// sides. One point is tested, so a pair hidden there and seen elsewhere goes unreported.
#include <algorithm>
#include <cmath>

#include "capture/diagnose/checks.h"
#include "capture/diagnose/finding_json.h"
#include "capture/lint/checks.h"
#include "renderer/scene/fit_inside.h"
#include "renderer/scene/surface_pairs.h"

namespace ds::lint {
namespace {

struct PairContext {
    const scene::Scene& scene;
    view::DepthConfig chosen;
    double seen_to = 0.0;             // checks.h: the scene's farthest corner from the first view
    std::vector<int64_t> decal_base;  // per instance: its base, or -1
};

constexpr double kLift = 1e-3;

// Whether a ray from `from` along `dir` meets a back face first (no hit: open space).
bool starts_inside(const scene::Scene& scene, const glm::dvec3& from, const glm::dvec3& dir) {
    const float reach = 2.0f * glm::length(scene.bounds.extent()) + 1.0f;
    std::optional<scene::RayHit> nearest;
    for (const scene::RayHit& h : scene::cast_ray(scene, glm::vec3(from), glm::vec3(dir), reach))
        if (!nearest || h.t < nearest->t) nearest = h;
    return nearest && !nearest->front && !nearest->double_sided;
}

bool enclosed(const PairContext& c, const scene::SurfacePair& p) {
    const glm::dvec3 n = glm::normalize(p.normal);
    const double lift =
        kLift * (std::max({std::abs(p.point.x), std::abs(p.point.y), std::abs(p.point.z)}) + 1.0);
    const double beyond = p.max_gap + lift;  // past both surfaces of a near pair
    if (!starts_inside(c.scene, p.point + n * beyond, n)) return false;
    const scene::Material& ma = c.scene.instance_material(p.a);
    const scene::Material& mb = c.scene.instance_material(p.b);
    if (!ma.double_sided && !mb.double_sided) return true;
    return starts_inside(c.scene, p.point - n * beyond, -n);
}

bool decal_related(const PairContext& c, uint32_t a, uint32_t b) {
    const int64_t ba = c.decal_base[a], bb = c.decal_base[b];
    return ba == int64_t(b) || bb == int64_t(a) || (ba >= 0 && ba == bb);
}

Finding pair_finding(const PairContext& c, const scene::SurfacePair& p, const char* code,
                     Severity severity) {
    Finding f;
    f.code = code;
    f.severity = severity;
    f.detector = "surface_pairs";
    f.surfaces = {diagnose::surface_of(c.scene, p.a), diagnose::surface_of(c.scene, p.b)};
    f.pointer = f.surfaces.front().pointer;
    return f;
}

std::string pair_label(const Finding& f) {
    return diagnose::label(f.surfaces[0]) + " and " + diagnose::label(f.surfaces[1]);
}

Finding duplicate_finding(const PairContext& c, const scene::SurfacePair& p) {
    Finding f = pair_finding(c, p, "DUPLICATE_INSTANCE", Severity::Error);
    f.magnitude = {p.overlap_area, "scene units^2"};
    f.message = pair_label(f) + " are the same triangles at the same place (" + g3(p.overlap_area) +
                " scene units^2): they Z-fight wherever they are drawn";
    f.fix = "remove one of the two nodes (or its copied mesh)";
    return f;
}

Finding coplanar_finding(const PairContext& c, const scene::SurfacePair& p) {
    Finding f = pair_finding(c, p, "COPLANAR_OVERLAP", Severity::Error);
    f.magnitude = {p.overlap_area, "scene units^2"};
    f.message = pair_label(f) + " overlap in one plane over " + g3(p.overlap_area) +
                " scene units^2 (" + std::to_string(p.triangle_pairs) +
                " triangle pairs) and neither lies on the other as a decal: they Z-fight there";
    f.fix =
        "cut the overlap out of one, move one off the plane by more than a depth step, or "
        "make one a decal (all of it lying on the other)";
    return f;
}

std::optional<Finding> near_finding(const PairContext& c, const scene::SurfacePair& p) {
    Finding f = pair_finding(c, p, "NEAR_COPLANAR_FIGHT", Severity::Info);
    f.values.push_back({"gap", p.min_gap});
    std::string distances;
    std::optional<double> chosen, nearest;
    for (const view::DepthConfig& format : every_format(c.chosen)) {
        const std::optional<double> d = fight_distance(format, p.min_gap, c.seen_to);
        const std::string name = depth_name(format);
        distances += "; " + name + ": " + (d ? "beyond " + g3(*d) : "never");
        if (!d) continue;
        f.values.push_back({name, *d});
        nearest = std::min(nearest.value_or(*d), *d);
        if (name == depth_name(c.chosen)) chosen = d;
    }
    if (!nearest) return std::nullopt;
    f.severity = chosen ? Severity::Warning : Severity::Info;
    f.magnitude = {chosen.value_or(*nearest), "scene units"};
    f.message = pair_label(f) + " are parallel, overlap and lie " + g3(p.min_gap) +
                " apart: seen head-on they store one depth " +
                (chosen ? "beyond " + g3(*chosen) + " in " + depth_name(c.chosen)
                        : "only in other formats than " + depth_name(c.chosen)) +
                " (planes " + g3(c.chosen.znear) + ".." + g3(c.chosen.zfar) +
                ", the scene within " + g3(c.seen_to) + distances + ")";
    f.fix =
        "move them apart by more than a depth step at the distance they are seen from, or "
        "remove the hidden one";
    return f;
}

}  // namespace

void check_surface_pairs(const Input& in, Output& out) {
    out.ran.push_back("surface_pairs");
    const scene::Camera& camera = in.views.empty() ? in.scene.camera : in.views.front().camera;
    PairContext c{in.scene, depth_config(in.settings, camera), seen_to(in.scene, camera),
                  std::vector<int64_t>(in.scene.instances.size(), -1)};
    for (const scene::Decal& d : in.scene.decals) c.decal_base.at(d.instance) = d.base;
    double reach = coarsest_step(c.chosen, c.seen_to);
    for (const view::DepthConfig& f : every_format(c.chosen))
        if (f.bits != 16) reach = std::max(reach, coarsest_step(f, c.seen_to));
    const std::vector<scene::SurfacePair> pairs = scene::find_surface_pairs(
        in.scene.meshes, in.scene.materials, in.scene.instances, {.near_gap_max = reach});
    for (const scene::SurfacePair& p : pairs) {
        if (p.kind == scene::PairKind::Duplicate) out.findings.push_back(duplicate_finding(c, p));
        if (p.kind == scene::PairKind::Coplanar && !decal_related(c, p.a, p.b) && !enclosed(c, p))
            out.findings.push_back(coplanar_finding(c, p));
        if (p.kind == scene::PairKind::Near && !enclosed(c, p))
            if (std::optional<Finding> f = near_finding(c, p)) out.findings.push_back(*f);
    }
}

}  // namespace ds::lint
