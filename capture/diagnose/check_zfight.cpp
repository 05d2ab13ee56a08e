// ZFIGHT (error): two surfaces within zfight_steps depth steps of each other where one of them
// won the prepass: the image flickers between them. From the zfight pass's pairs (passes/
// zfight.h); a classified overlay and its base are check_decals' (DECAL_ZFIGHT). The pairs of
// one pair of meshes beyond the first kPairsPerMeshes fold into one finding.
#include <algorithm>
#include <cstdio>
#include <map>

#include "capture/diagnose/checks.h"
#include "capture/diagnose/finding_json.h"
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

// The pairs of one pair of meshes beyond the first kPairsPerMeshes (a fan of rods meeting at a
// hub fights at every neighbour): one finding for the rest, their pixels together.
constexpr size_t kPairsPerMeshes = 8;

Finding folded_finding(const CheckInput& in, const ZfightResult& z, uint32_t first, size_t count,
                       uint64_t px, std::vector<uint32_t> pixels) {
    Finding f = zfight_finding(in, z, first, {});
    const FindingSurface& a = f.surfaces.front();
    const FindingSurface& b = f.surfaces.back();
    f.magnitude = {double(px), "px"};
    f.message = "Z-fight: " + std::to_string(count) + " more pairs of mesh " + a.mesh + " × mesh " +
                b.mesh + ", " + grouped(double(px)) + " px (" + depth_label(in.settings) + ")";
    for (FindingSurface& s : f.surfaces) s.node = s.pointer = "";  // many nodes
    f.pointer.clear();
    normalise_pixels(pixels);
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
    struct Fold {
        size_t pairs = 0, folded = 0;
        uint32_t first = 0;
        uint64_t px = 0;
        std::vector<uint32_t> pixels;
    };
    std::map<std::pair<std::string, std::string>, Fold> meshes;  // pairs sorted by pixels
    std::vector<std::pair<std::string, std::string>> order;
    for (uint32_t i = 0; i < z->pairs.size(); ++i) {
        const ZfightPair& pair = z->pairs[i];
        if (is_decal_pair(in.scene, pair.a, pair.b)) continue;
        Fold& fold = meshes[{pair.a.mesh, pair.b.mesh}];
        if (++fold.pairs <= kPairsPerMeshes) {
            out.findings.push_back(zfight_finding(in, *z, i, std::move(pixels[i])));
            continue;
        }
        if (fold.folded++ == 0) {
            fold.first = i;
            order.push_back({pair.a.mesh, pair.b.mesh});
        }
        fold.px += pair.pixels;
        fold.pixels.insert(fold.pixels.end(), pixels[i].begin(), pixels[i].end());
    }
    for (const auto& key : order) {
        Fold& fold = meshes[key];
        out.findings.push_back(
            folded_finding(in, *z, fold.first, fold.folded, fold.px, std::move(fold.pixels)));
    }
}

}  // namespace ds::diagnose
