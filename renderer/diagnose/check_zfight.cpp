// ZFIGHT (error): two surfaces within zfight_steps depth steps of each other where one of them
// won the prepass: the image flickers between them. From the zfight pass's pairs (passes/
// zfight.h); a classified overlay and its base are check_decals' (DECAL_ZFIGHT).
#include <algorithm>
#include <cstdio>

#include "renderer/diagnose/checks.h"
#include "renderer/diagnose/finding_json.h"
#include "renderer/passes/zfight.h"

namespace ds::diagnose {
namespace {

// "1.2e-05": a gap in scene units, short.
std::string short_number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", v);
    return text;
}

// The least gap in scene units over a pair's hits.
float least_gap(const ZfightResult& z, uint32_t pair) {
    float least = -1.0f;
    for (const ZfightHit& h : z.hits)
        if (h.pair == pair && (least < 0.0f || h.gap < least)) least = h.gap;
    return std::max(least, 0.0f);
}

Finding zfight_finding(const CheckInput& in, const ZfightResult& z, uint32_t index,
                       std::vector<uint32_t> pixels) {
    const ZfightPair& pair = z.pairs[index];
    const FindingSurface a = surface_named(in.scene, pair.a);
    const FindingSurface b = surface_named(in.scene, pair.b);
    const bool same = pair.a == pair.b;
    const std::string who =
        same ? "overlapping triangles of " + label(a) : label(a) + " × " + label(b);
    const std::string gap = pair.min_steps == 0 ? "gap 0 steps (coplanar)"
                                                : "gap ≤ " + std::to_string(pair.min_steps) +
                                                      (pair.min_steps == 1 ? " step" : " steps");
    Finding f;
    f.code = "ZFIGHT";
    f.severity = Severity::Error;
    f.detector = "zfight";
    f.magnitude = {double(pair.pixels), "px"};
    f.message = "Z-fight: " + who + ", " + grouped(double(pair.pixels)) + " px, " + gap + " (" +
                depth_label(in.settings) + ")";
    if (pair.min_steps == 0)
        f.fix = same ? "remove the overlapping triangles from the mesh"
                     : "classify the overlay as a decal (it must lie exactly on its base; "
                       "decal_pass draws it after) or offset it";
    else
        f.fix = "separate them by more than " + std::to_string(z.steps) +
                " depth steps (least gap here " + short_number(least_gap(z, index)) +
                " scene units) or gain precision (depth_format=d32f, reverse_z=on, a larger "
                "znear)";
    f.surfaces = same ? std::vector<FindingSurface>{a} : std::vector<FindingSurface>{a, b};
    f.pointer = a.pointer;
    f.pixels = std::move(pixels);
    return f;
}

}  // namespace

void check_zfight(const CheckInput& in, CheckOutput& out) {
    const ZfightResult* z = in.measured.find<ZfightResult>();
    if (!z) {
        out.skip("zfight", frame_skip_reason(in.measured, "zfight", "zfight").value_or("not run"));
        return;
    }
    out.ran.push_back("zfight");
    std::vector<std::vector<uint32_t>> pixels = pair_pixels(*z);
    for (uint32_t i = 0; i < z->pairs.size(); ++i) {
        if (is_decal_pair(in.scene, z->pairs[i].a, z->pairs[i].b)) continue;
        out.findings.push_back(zfight_finding(in, *z, i, std::move(pixels[i])));
    }
}

}  // namespace ds::diagnose
