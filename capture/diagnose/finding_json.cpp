#include "capture/diagnose/finding_json.h"

#include <cmath>
#include <cstdio>

namespace ds::diagnose {
namespace {

nlohmann::json vec3_json(const glm::vec3& v) {
    return nlohmann::json::array({double(v.x), double(v.y), double(v.z)});
}

}  // namespace

nlohmann::json camera_json(const scene::Camera& c) {
    return {{"position", vec3_json(c.position)},
            {"forward", vec3_json(c.forward)},
            {"up", vec3_json(c.up)},
            {"yfov", double(c.yfov)},
            {"znear", double(c.znear)},
            {"zfar", double(c.zfar)}};
}

namespace {

nlohmann::json surfaces_json(const std::vector<FindingSurface>& surfaces) {
    nlohmann::json out = nlohmann::json::array();
    for (const FindingSurface& s : surfaces)
        out.push_back(
            {{"mesh", s.mesh}, {"material", s.material}, {"node", s.node}, {"pointer", s.pointer}});
    return out;
}

}  // namespace

std::string grouped(double value) {
    const double whole = std::floor(std::fabs(value));
    if (std::fabs(value) - whole > 1e-9 || std::fabs(value) >= 1e15) {
        char text[64];
        std::snprintf(text, sizeof text, "%.2f", value);
        return text;
    }
    std::string digits = std::to_string(static_cast<unsigned long long>(whole));
    for (int i = int(digits.size()) - 3; i > 0; i -= 3) digits.insert(size_t(i), ",");
    return (value < 0 ? "-" : "") + digits;
}

nlohmann::json finding_json(const Finding& f) {
    nlohmann::json j = {{"code", f.code},
                        {"message", f.message},
                        {"severity", int(f.severity)},
                        {"pointer", f.pointer},
                        {"magnitude", {{"value", f.magnitude.value}, {"unit", f.magnitude.unit}}},
                        {"surfaces", surfaces_json(f.surfaces)},
                        {"fix", f.fix},
                        {"detector", f.detector}};
    for (const auto& [name, value] : f.values) j["values"][name] = value;
    return j;
}

nlohmann::json diagnosis_json(const Diagnosis& d) {
    nlohmann::json messages = nlohmann::json::array();
    for (const Finding& f : d.findings) messages.push_back(finding_json(f));
    nlohmann::json skipped = nlohmann::json::array();
    for (const SkippedDetector& s : d.skipped)
        skipped.push_back({{"detector", s.detector}, {"reason", s.reason}});
    nlohmann::json settings = nlohmann::json::object();
    for (const auto& [name, value] : d.settings) settings[name] = value;
    return {{"scene", {{"name", d.scene}, {"source", d.scene_source}}},
            {"camera", camera_json(d.camera)},
            {"size", {{"width", d.width}, {"height", d.height}}},
            {"settings", settings},
            {"measurement_knobs", d.measurement_knobs},
            {"detectors", d.detectors},
            {"frames", d.frames},
            {"issues",
             {{"numErrors", d.count(Severity::Error)},
              {"numWarnings", d.count(Severity::Warning)},
              {"numInfos", d.count(Severity::Info)},
              {"numHints", d.count(Severity::Hint)},
              {"messages", messages},
              {"truncated", false}}},
            {"skipped", skipped}};
}

std::string diagnosis_text(const Diagnosis& d) {
    std::string out = "diagnose " + d.scene + " " + std::to_string(d.width) + "x" +
                      std::to_string(d.height) + " (" + std::to_string(d.frames) + " frames)\n";
    for (const Finding& f : d.findings) {
        char head[32];
        std::snprintf(head, sizeof head, "%-7s %-18s ", severity_name(f.severity), f.code.c_str());
        out += head + f.message + "\n";
        if (!f.fix.empty()) out += std::string(27, ' ') + "fix: " + f.fix + "\n";
    }
    if (d.findings.empty()) out += "no findings\n";
    for (const SkippedDetector& s : d.skipped)
        out += "skipped: " + s.detector + " (" + s.reason + ")\n";
    const auto counted = [&](Severity s, const char* one, const char* many) {
        const size_t n = d.count(s);
        return std::to_string(n) + " " + (n == 1 ? one : many);
    };
    out += counted(Severity::Error, "error", "errors") + ", " +
           counted(Severity::Warning, "warning", "warnings") + ", " +
           counted(Severity::Info, "info", "infos") + ", " +
           counted(Severity::Hint, "hint", "hints") + "\n";
    return out;
}

}  // namespace ds::diagnose
