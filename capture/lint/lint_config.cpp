#include "capture/lint/lint_config.h"

#include <algorithm>
#include <cmath>
#include <regex>

#include <nlohmann/json.hpp>

#include "capture/layer_capture_data.h"
#include "renderer/common/error.h"

namespace ds::lint {
namespace {

std::vector<std::string> code_list(const nlohmann::json& j, const std::string& key) {
    if (!j.is_array()) throw Error("\"" + key + "\" must be an array of codes");
    static const std::regex kCode("[A-Z][A-Z0-9_]*");
    std::vector<std::string> out;
    for (const nlohmann::json& c : j) {
        if (!c.is_string() || !std::regex_match(c.get<std::string>(), kCode))
            throw Error("\"" + key + "\": " + c.dump() + " is not a code (UPPER_SNAKE)");
        out.push_back(c.get<std::string>());
    }
    return out;
}

Severity severity_of(const std::string& code, const nlohmann::json& v) {
    if (v.is_number_integer() && v.get<int64_t>() >= 0 && v.get<int64_t>() <= 3)
        return Severity(v.get<int>());
    if (v.is_string())
        for (const Severity s :
             {Severity::Error, Severity::Warning, Severity::Info, Severity::Hint})
            if (v.get<std::string>() == diagnose::severity_name(s)) return s;
    throw Error("\"override\": " + code + ": " + v.dump() +
                " is no severity (0..3, error, warning, info or hint)");
}

double threshold(const nlohmann::json& t, const char* key, double fallback, double lo, double hi) {
    if (!t.contains(key)) return fallback;
    const nlohmann::json& v = t[key];
    if (!v.is_number() || !(v.get<double>() >= lo && v.get<double>() <= hi))
        throw Error("\"thresholds\": \"" + std::string(key) + "\": " + v.dump() +
                    " is not a number in " + nlohmann::json(lo).dump() + ".." +
                    nlohmann::json(hi).dump());
    return v.get<double>();
}

Thresholds parse_thresholds(const nlohmann::json& t) {
    if (!t.is_object()) throw Error("\"thresholds\" must be an object");
    for (const auto& [key, value] : t.items())
        if (key != "overdraw" && key != "mesh_overdraw" && key != "min_steps_per_unit" &&
            key != "coverage_drop")
            throw Error("\"thresholds\": unknown key \"" + key +
                        "\" (overdraw, mesh_overdraw, min_steps_per_unit, coverage_drop)");
    const Thresholds d;
    return {
        .overdraw = threshold(t, "overdraw", d.overdraw, 1.0, 1e6),
        .mesh_overdraw = threshold(t, "mesh_overdraw", d.mesh_overdraw, 1.0, 1e6),
        .min_steps_per_unit = threshold(t, "min_steps_per_unit", d.min_steps_per_unit, 0.0, 1e12),
        .coverage_drop = threshold(t, "coverage_drop", d.coverage_drop, 0.0, 1.0)};
}

}  // namespace

Config parse_config(const nlohmann::json& j) {
    if (!j.is_object()) throw Error("a lint config is a JSON object");
    Config c;
    for (const auto& [key, value] : j.items()) {
        if (key == "ignore")
            c.ignore = code_list(value, key);
        else if (key == "only")
            c.only = code_list(value, key);
        else if (key == "thresholds")
            c.thresholds = parse_thresholds(value);
        else if (key == "max-issues") {
            if (!value.is_number_unsigned())
                throw Error("\"max-issues\": " + value.dump() + " is not a whole number >= 0");
            c.max_issues = value.get<size_t>();
        } else if (key == "override") {
            if (!value.is_object()) throw Error("\"override\" must be an object {CODE: severity}");
            for (const auto& [code, sev] : value.items())
                c.overrides[code] = severity_of(code, sev);
        } else {
            throw Error("unknown key \"" + key +
                        "\" (ignore, only, override, max-issues, thresholds)");
        }
    }
    if (!c.ignore.empty() && !c.only.empty())
        throw Error("\"ignore\" and \"only\" cannot both be given");
    return c;
}

Config read_config(const std::filesystem::path& file) {
    const nlohmann::json j = capture::read_json_file(file);  // "FILE: why" when unreadable or malformed
    try {
        return parse_config(j);
    } catch (const Error& e) {
        throw InputError(file.string() + ": " + e.what());
    }
}

void apply_config(const Config& c, Report& r) {
    const auto listed = [](const std::vector<std::string>& list, const std::string& code) {
        return std::find(list.begin(), list.end(), code) != list.end();
    };
    std::erase_if(r.findings, [&](const Finding& f) {
        return c.only.empty() ? listed(c.ignore, f.code) : !listed(c.only, f.code);
    });
    for (Finding& f : r.findings)
        if (const auto o = c.overrides.find(f.code); o != c.overrides.end()) f.severity = o->second;
    diagnose::rank(r.findings);
    if (c.max_issues && r.findings.size() > c.max_issues) {
        r.findings.resize(c.max_issues);
        r.truncated = true;
    }
}

}  // namespace ds::lint
