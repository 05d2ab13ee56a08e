// ALPHA_MODE (warning): a material whose alpha mode does not fit its alpha. Alpha is
// baseColorFactor.a times the base colour texture's alpha (8-bit texels).
// - BLEND whose alpha is only 0 or 1: it could be MASK (some 0) or OPAQUE (all 1), drawn in
//   the prepass instead of sorted and blended after everything.
// - OPAQUE with meaningful alpha: baseColorFactor.a below 1, or at least kMeaningfulShare of
//   the texels below one half (what a MASK at cutoff 0.5 would cut): OPAQUE ignores it.
// - MASK whose texture's uploaded mips lose more than Thresholds::coverage_drop of level 0's
//   coverage at a level of at least 16 texels a side (diagnose's alpha-coverage check, the one
//   CPU implementation in renderer/scene/alpha_coverage.*): the cut-outs thin with distance.
#include <algorithm>

#include "capture/diagnose/checks.h"
#include "capture/lint/checks.h"

namespace ds::lint {
namespace {

constexpr double kMeaningfulShare = 0.01;
constexpr size_t kMaxSurfaces = 8;  // a finding names at most this many

struct AlphaFacts {
    bool only_0_or_1 = true;
    bool any_0 = false;
    double share_below_half = 0.0;
};

AlphaFacts alpha_facts(const scene::Scene& scene, const scene::Material& m) {
    AlphaFacts a;
    const float factor = m.base_color_factor.a;
    const scene::Image* image = nullptr;
    if (m.base_color.present() && size_t(m.base_color.texture) < scene.textures.size()) {
        const uint32_t i = scene.textures[size_t(m.base_color.texture)].image;
        if (i < scene.images.size() && !scene.images[i].rgba8.empty()) image = &scene.images[i];
    }
    if (!image) {
        a.only_0_or_1 = factor == 0.0f || factor == 1.0f;
        a.any_0 = factor == 0.0f;
        a.share_below_half = factor < 0.5f ? 1.0 : 0.0;
        return a;
    }
    uint64_t below = 0, texels = image->rgba8.size() / 4;
    for (size_t t = 3; t < image->rgba8.size(); t += 4) {
        const float alpha = factor * float(image->rgba8[t]) / 255.0f;
        a.only_0_or_1 = a.only_0_or_1 && (alpha == 0.0f || alpha == 1.0f);
        a.any_0 = a.any_0 || alpha == 0.0f;
        below += alpha < 0.5f ? 1 : 0;
    }
    a.share_below_half = texels ? double(below) / double(texels) : 0.0;
    return a;
}

Finding mode_finding(const scene::Scene& scene, uint32_t material, std::string message,
                     std::string fix, double magnitude, std::string unit) {
    Finding f;
    f.code = "ALPHA_MODE";
    f.severity = Severity::Warning;
    f.detector = "alpha_mode";
    f.pointer = "/materials/" + std::to_string(material);
    f.message = "material " + scene.materials[material].name + ": " + std::move(message);
    f.fix = std::move(fix);
    f.magnitude = {magnitude, std::move(unit)};
    f.surfaces = diagnose::material_surfaces(scene, material, kMaxSurfaces);
    return f;
}

std::optional<Finding> material_finding(const scene::Scene& scene, uint32_t material) {
    const scene::Material& m = scene.materials[material];
    if (m.alpha_mode == scene::AlphaMode::Mask) return std::nullopt;
    const AlphaFacts a = alpha_facts(scene, m);
    if (m.alpha_mode == scene::AlphaMode::Blend && a.only_0_or_1)
        return mode_finding(
            scene, material,
            a.any_0 ? "BLEND, but its alpha is only 0 or 1: it could be MASK"
                    : "BLEND, but its alpha is 1 everywhere: it could be OPAQUE",
            a.any_0 ? "alphaMode MASK (drawn in the prepass, no sorting)" : "alphaMode OPAQUE",
            a.any_0 ? 1.0 : 0.0, "share of alpha 0 or 1");
    const bool meaningful = m.base_color_factor.a < 1.0f || a.share_below_half >= kMeaningfulShare;
    if (m.alpha_mode == scene::AlphaMode::Opaque && meaningful)
        return mode_finding(scene, material,
                            "OPAQUE, but its alpha means something (baseColorFactor.a " +
                                g3(m.base_color_factor.a) + ", " + g3(a.share_below_half * 100.0) +
                                " % of it below 0.5): OPAQUE ignores it",
                            "alphaMode MASK (cut-outs) or BLEND (translucency), or remove the "
                            "alpha channel",
                            a.share_below_half * 100.0, "%");
    return std::nullopt;
}

}  // namespace

void check_alpha_mode(const Input& in, Output& out) {
    out.ran.push_back("alpha_mode");
    std::vector<bool> used(in.scene.materials.size(), false);
    for (const scene::Instance& i : in.scene.instances)
        used.at(in.scene.meshes.at(i.mesh).material) = true;
    for (uint32_t m = 0; m < in.scene.materials.size(); ++m)
        if (std::optional<Finding> f = used[m] ? material_finding(in.scene, m) : std::nullopt)
            out.findings.push_back(std::move(*f));
    for (Finding& f :
         diagnose::alpha_coverage_findings(in.scene, in.settings, in.thresholds.coverage_drop)) {
        f.code = "ALPHA_MODE";
        f.detector = "alpha_mode";
        out.findings.push_back(std::move(f));
    }
}

}  // namespace ds::lint
