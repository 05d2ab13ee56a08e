#include "capture/layer_depth_report.h"

#include <algorithm>

namespace ds::capture {

namespace {

using nlohmann::json;

// {draw, instance, name}: the draw as the report names it.
json named(const json& who, const json& draws) {
    json out = who;
    out["name"] = draws.at(who.at("draw").get<size_t>()).at("name");
    return out;
}

json zfight_section(const json& report) {
    const json& draws = report.at("draws");
    json pairs = json::array(), passes = json::array();
    uint64_t pixels = 0, dropped = 0;
    for (const json& pass : report.at("passes")) {
        if (!pass.contains("zfight")) continue;
        const json& z = pass.at("zfight");
        pixels += z.at("pixels").get<uint64_t>();
        dropped = std::max(dropped, z.at("dropped_records").get<uint64_t>());
        for (const json& p : z.at("pairs"))
            pairs.push_back({{"a", named(p.at("a"), draws)},
                             {"b", named(p.at("b"), draws)},
                             {"pixels", p.at("pixels")},
                             {"min_steps", p.at("min_steps")},
                             {"pass", pass.at("name")}});
        passes.push_back({{"pass", pass.at("name")},
                          {"depth_format", pass.at("depth_format")},
                          {"pixels", z.at("pixels")},
                          {"image", pass.at("images").at("zfight")}});
    }
    std::stable_sort(pairs.begin(), pairs.end(), [](const json& a, const json& b) {
        return a.at("pixels").get<uint64_t>() > b.at("pixels").get<uint64_t>();
    });
    json out = {{"steps", report.at("settings").at("zfight_steps")},
                {"pixels", pixels},
                {"pairs", pairs},
                {"passes", passes}};
    if (dropped) out["dropped_records"] = dropped;
    return out;
}

json equal_section(const json& report) {
    const json& draws = report.at("draws");
    json surfaces = json::array(), passes = json::array();
    uint64_t holes = 0, multiple = 0;
    for (const json& pass : report.at("passes")) {
        if (!pass.contains("equal_check")) continue;
        const json& e = pass.at("equal_check");
        holes += e.at("holes").get<uint64_t>();
        multiple += e.at("multiple").get<uint64_t>();
        for (const json& s : e.at("surfaces")) {
            json entry = named(s, draws);
            entry["pass"] = pass.at("name");
            surfaces.push_back(entry);
        }
        const json& prepass = report.at("passes").at(e.at("prepass").get<size_t>());
        passes.push_back({{"pass", pass.at("name")},
                          {"prepass", prepass.at("name")},
                          {"holes", e.at("holes")},
                          {"multiple", e.at("multiple")},
                          {"image", pass.at("images").at("equal_check")}});
    }
    std::stable_sort(surfaces.begin(), surfaces.end(), [](const json& a, const json& b) {
        return a.at("holes").get<uint64_t>() + a.at("multiple").get<uint64_t>() >
               b.at("holes").get<uint64_t>() + b.at("multiple").get<uint64_t>();
    });
    return {{"holes", holes}, {"multiple", multiple}, {"surfaces", surfaces}, {"passes", passes}};
}

}  // namespace

void add_layer_depth_sections(json& report) {
    const json& settings = report.at("settings");
    if (settings.at("zfight").get<bool>()) report["zfight"] = zfight_section(report);
    if (settings.at("equal_check").get<bool>()) report["equal_check"] = equal_section(report);
}

}  // namespace ds::capture
