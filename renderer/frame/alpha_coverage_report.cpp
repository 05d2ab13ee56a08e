#include "renderer/frame/alpha_coverage_report.h"

#include <nlohmann/json.hpp>

namespace ds {
namespace {

nlohmann::json levels_json(const std::vector<scene::LevelCoverage>& levels) {
    nlohmann::json out = nlohmann::json::array();
    for (const scene::LevelCoverage& l : levels)
        out.push_back({{"level", l.level},
                       {"width", l.width},
                       {"height", l.height},
                       {"coverage", l.coverage},
                       {"relative", l.relative}});
    return out;
}

}  // namespace

nlohmann::json alpha_coverage_json(const AlphaCoverageResult& result) {
    nlohmann::json materials = nlohmann::json::array();
    for (const scene::MaterialAlphaCoverage& m : result.materials) {
        nlohmann::json entry = {{"material", m.material_name},
                                {"material_index", m.material},
                                {"image", m.image_name},
                                {"image_index", m.image},
                                {"cutoff", m.cutoff},
                                {"factor_alpha", m.factor},
                                {"mode", scene::to_string(m.mode)},
                                {"box", levels_json(m.box)}};
        if (m.mode == scene::AlphaMipMode::Preserve) entry["uploaded"] = levels_json(m.uploaded);
        materials.push_back(std::move(entry));
    }
    return {{"mode", scene::to_string(result.mode)},
            {"materials", std::move(materials)},
            {"note",
             "per MASK material with a base colour texture: coverage is the fraction of a mip "
             "level's texels whose alpha x factor_alpha >= cutoff (the effective cutoff), "
             "relative its ratio to level 0's; box: the 2x2 box chain (what vkCmdBlitImage "
             "makes), uploaded: the chain alpha_mip_coverage=preserve uploads instead"}};
}

void alpha_coverage_report(const AlphaCoverageResult& result, const FrameResult&,
                           nlohmann::json& report) {
    report["alpha_coverage"] = alpha_coverage_json(result);
}

}  // namespace ds
