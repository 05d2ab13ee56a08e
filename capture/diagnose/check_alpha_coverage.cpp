// ALPHA_COVERAGE (warning): a MASK material whose base colour, at a mip level of at least
// kCoverageMinLevel texels a side, passes its alpha test on more than kCoverageMaxDrop fewer texels
// than at level 0, in the chain the renderer uploads under the user's settings (the box chain, or
// alpha_mip_coverage=preserve's): alpha-tested foliage thins out with distance. Computed on
// the CPU from the scene (scene/alpha_coverage.h, what report.json's alpha_coverage shows), at
// each material's effective cutoff; it needs no frame.
#include <cmath>
#include <cstdio>

#include "capture/diagnose/checks.h"
#include "renderer/scene/alpha_coverage.h"

namespace ds::diagnose {
namespace {

constexpr uint32_t kCoverageMinLevel = 16;  // smaller levels have too few texels to keep a share
constexpr double kCoverageMaxDrop = 0.2;    // of level 0's coverage
constexpr size_t kCoverageMaxSurfaces = 8;

std::string coverage_percent(double fraction) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f %%", fraction * 100.0);
    return text;
}

Finding coverage_finding(const scene::Scene& scene, const scene::MaterialAlphaCoverage& c,
                         const std::vector<scene::LevelCoverage>& levels,
                         const scene::CoverageDrop& drop) {
    const scene::LevelCoverage& at = levels.at(drop.level);
    Finding f;
    f.code = "ALPHA_COVERAGE";
    f.severity = Severity::Warning;
    f.detector = "alpha_coverage";
    f.magnitude = {std::round(drop.drop * 1000.0) / 10.0, "%"};
    char cutoff[16];
    std::snprintf(cutoff, sizeof cutoff, "%.3g", double(c.cutoff));
    f.message = "alpha coverage: material " + c.material_name + " (image " + c.image_name +
                ", cutoff " + cutoff + ", " + scene::to_string(c.mode) + " mips) passes on " +
                coverage_percent(levels.front().coverage) + " of level 0's texels but " +
                coverage_percent(at.coverage) + " at level " + std::to_string(at.level) + " (" +
                std::to_string(at.width) + "x" + std::to_string(at.height) +
                "): " + coverage_percent(drop.drop) +
                " of it lost, so its cut-outs thin out with distance";
    f.fix = c.mode == scene::AlphaMipMode::Box
                ? "alpha_mip_coverage=preserve (mips whose alpha keeps level 0's coverage)"
                : "author the texture's alpha so its mips can keep the coverage (preserve scales "
                  "a level's alpha as a whole), or alpha_level0=on";
    f.surfaces = material_surfaces(scene, c.material, kCoverageMaxSurfaces);
    if (!f.surfaces.empty()) f.pointer = f.surfaces.front().pointer;
    return f;
}

}  // namespace

std::vector<Finding> alpha_coverage_findings(const scene::Scene& scene, const Settings& settings,
                                             double max_drop) {
    std::vector<Finding> out;
    for (const scene::MaterialAlphaCoverage& c : scene::scene_alpha_coverage(scene, settings)) {
        const std::vector<scene::LevelCoverage>& levels =
            c.mode == scene::AlphaMipMode::Preserve ? c.uploaded : c.box;
        const std::optional<scene::CoverageDrop> drop =
            scene::worst_coverage_drop(levels, kCoverageMinLevel);
        if (drop && drop->drop > max_drop) out.push_back(coverage_finding(scene, c, levels, *drop));
    }
    return out;
}

void check_alpha_coverage(const CheckInput& in, CheckOutput& out) {
    if (!has_masked_texture(in.scene)) {
        out.skip("alpha_coverage", "the scene has no MASK material with a base colour texture");
        return;
    }
    out.ran.push_back("alpha_coverage");
    for (Finding& f : alpha_coverage_findings(in.scene, in.settings, kCoverageMaxDrop))
        out.findings.push_back(std::move(f));
}

bool has_masked_texture(const scene::Scene& scene) {
    for (uint32_t m = 0; m < scene.materials.size(); ++m)
        if (scene::masked_base_color_image(scene, m)) return true;
    return false;
}

}  // namespace ds::diagnose
