#include "capture/lint/lint_json.h"

#include <cstdio>

#include "capture/diagnose/finding_json.h"
#include "renderer/common/version.h"

namespace ds::lint {
namespace {

size_t count_of(const Report& r, Severity s) {
    size_t n = 0;
    for (const Finding& f : r.findings) n += f.severity == s ? 1 : 0;
    return n;
}

std::string mime_type(const std::string& source) {
    return source.ends_with(".glb") || source.ends_with(".GLB") ? "model/gltf-binary"
                                                                : "model/gltf+json";
}

nlohmann::json asset_info(const scene::Scene& scene) {
    uint64_t vertices = 0;
    for (const scene::Instance& i : scene.instances)
        vertices += scene.meshes[i.mesh].vertices.size();
    bool textures = !scene.textures.empty();
    return {{"materialCount", scene.materials.size()},
            {"hasTextures", textures},
            {"drawCallCount", scene.draw_groups.size()},
            {"instanceCount", scene.instances.size()},
            {"totalVertexCount", vertices},
            {"totalTriangleCount", scene.triangle_count()}};
}

nlohmann::json views_json(const std::vector<View>& views) {
    nlohmann::json out = nlohmann::json::array();
    for (const View& v : views)
        out.push_back({{"name", v.name},
                       {"pointer", v.pointer},
                       {"camera", diagnose::camera_json(v.camera)}});
    return out;
}

}  // namespace

nlohmann::json report_json(const Report& r, const scene::Scene& scene) {
    nlohmann::json messages = nlohmann::json::array();
    for (const Finding& f : r.findings) messages.push_back(diagnose::finding_json(f));
    nlohmann::json skipped = nlohmann::json::array();
    for (const auto& s : r.skipped)
        skipped.push_back({{"check", s.detector}, {"reason", s.reason}});
    nlohmann::json settings = nlohmann::json::object();
    for (const auto& [name, value] : r.settings) settings[name] = value;
    return {{"uri", r.source},
            {"mimeType", mime_type(r.source)},
            {"validatorVersion", std::string("depthscope ") + version()},
            {"issues",
             {{"numErrors", count_of(r, Severity::Error)},
              {"numWarnings", count_of(r, Severity::Warning)},
              {"numInfos", count_of(r, Severity::Info)},
              {"numHints", count_of(r, Severity::Hint)},
              {"messages", messages},
              {"truncated", r.truncated}}},
            {"info", asset_info(scene)},
            {"scene", {{"name", r.scene}, {"source", r.source}}},
            {"views", views_json(r.views)},
            {"settings", settings},
            {"depth",
             {{"format", depth_name(r.depth)}, {"znear", r.depth.znear}, {"zfar", r.depth.zfar}}},
            {"checks", r.checks},
            {"skipped", skipped},
            {"images", r.images},
            {"frames", r.frames}};
}

std::string reports_text(const std::vector<Report>& reports, size_t max_lines) {
    std::string out;
    size_t totals[4] = {0, 0, 0, 0};
    for (const Report& r : reports) {
        for (const Severity s :
             {Severity::Error, Severity::Warning, Severity::Info, Severity::Hint})
            totals[int(s)] += count_of(r, s);
        out += "lint " + r.scene + " (" + r.source +
               "): " + std::to_string(count_of(r, Severity::Error)) + " errors, " +
               std::to_string(count_of(r, Severity::Warning)) + " warnings, " +
               std::to_string(count_of(r, Severity::Info)) + " infos" +
               (r.truncated ? " (truncated by max-issues)" : "") + "\n";
        for (size_t i = 0; i < r.findings.size() && i < max_lines; ++i) {
            const Finding& f = r.findings[i];
            char head[48];
            std::snprintf(head, sizeof head, "  %-7s %-19s ", diagnose::severity_name(f.severity),
                          f.code.c_str());
            out += head + f.message + "\n";
        }
        if (r.findings.size() > max_lines)
            out += "  … and " + std::to_string(r.findings.size() - max_lines) +
                   " more (--json FILE has them all)\n";
        for (const auto& s : r.skipped) out += "  skipped: " + s.detector + " (" + s.reason + ")\n";
    }
    if (reports.size() > 1)
        out += "total: " + std::to_string(totals[0]) + " errors, " + std::to_string(totals[1]) +
               " warnings, " + std::to_string(totals[2]) + " infos over " +
               std::to_string(reports.size()) + " scenes\n";
    return out;
}

}  // namespace ds::lint
