// tune alpha's table, JSON and plot (tune_report.h).
#include <cstdio>

#include "capture/tune/tune_report.h"

namespace ds::tune {
namespace {

constexpr uint32_t kPalette[] = {0x3a6fd8, 0xd8553a, 0x2e9e5b, 0x9b59b6, 0xc9a227, 0x1abc9c};

std::string point_text(const AlphaPoint& p) {
    char line[200];
    std::snprintf(line, sizeof line, "  %6.3f %-5s %9.4f %9llu %9llu %12llu %12llu", p.cutoff,
                  p.alpha_to_coverage ? "a2c" : "", p.coverage_error,
                  (unsigned long long)p.mismatched, (unsigned long long)p.material_pixels,
                  (unsigned long long)p.cost.discarded_fragments,
                  (unsigned long long)p.cost.shaded_fragments);
    std::string s = line;
    if (p.cost.frame_ms > 0) {
        std::snprintf(line, sizeof line, " %8.3f", p.cost.frame_ms);
        s += line;
    }
    return s;
}

nlohmann::json point_json(const AlphaPoint& p) {
    nlohmann::json j{{"cutoff", p.cutoff},
                     {"alpha_to_coverage", p.alpha_to_coverage},
                     {"coverage_error", p.coverage_error},
                     {"mismatched_pixels", p.mismatched},
                     {"material_pixels", p.material_pixels},
                     {"covered_pixels", p.covered},
                     {"discarded_fragments", p.cost.discarded_fragments},
                     {"shaded_fragments", p.cost.shaded_fragments}};
    if (p.cost.frame_ms > 0) j["frame_ms"] = p.cost.frame_ms;
    return j;
}

}  // namespace

std::string alpha_text(const AlphaTune& t) {
    std::string s = "reference: " + std::to_string(t.reference_factor) + "x" +
                    std::to_string(t.reference_factor) + " samples per pixel at " +
                    std::to_string(t.size.width) + "x" + std::to_string(t.size.height) + ", msaa " +
                    std::to_string(t.msaa) + "\n";
    for (const AlphaMaterial& m : t.materials) {
        char head[300];
        std::snprintf(head, sizeof head,
                      "material \"%s\" (cutoff %.3f, reference covers %llu px)\n", m.name.c_str(),
                      m.cutoff, (unsigned long long)m.reference_covered);
        s += head;
        s += "  cutoff        error  mismatch    pixels    discarded       shaded";
        s += t.cost_kind == CostKind::Ms ? "  GPU ms\n" : "\n";
        for (size_t i = 0; i < m.points.size(); ++i) {
            s += point_text(m.points[i]);
            if (int(i) == m.best) s += "  best";
            if (int(i) == m.current) s += "  current";
            s += "\n";
        }
        if (m.best >= 0) {
            const AlphaPoint& b = m.points[size_t(m.best)];
            char rec[300];
            std::snprintf(rec, sizeof rec,
                          "  recommended: --set material_alpha_cutoff=%s=%g%s (error %.4f)\n",
                          m.name.c_str(), b.cutoff,
                          b.alpha_to_coverage ? " --set alpha_to_coverage=on" : "",
                          b.coverage_error);
            s += rec;
        }
    }
    return s;
}

nlohmann::json alpha_json(const AlphaTune& t) {
    nlohmann::json materials = nlohmann::json::array();
    for (const AlphaMaterial& m : t.materials) {
        nlohmann::json points = nlohmann::json::array();
        for (const AlphaPoint& p : m.points) points.push_back(point_json(p));
        materials.push_back(
            {{"name", m.name},
             {"cutoff", m.cutoff},
             {"reference_covered_pixels", m.reference_covered},
             {"points", points},
             {"best", m.best < 0 ? nlohmann::json() : nlohmann::json(m.best)},
             {"current", m.current < 0 ? nlohmann::json() : nlohmann::json(m.current)}});
    }
    return {{"size", {t.size.width, t.size.height}},
            {"cost", cost_kind_name(t.cost_kind)},
            {"msaa", t.msaa},
            {"step", t.step},
            {"reference", {{"factor", t.reference_factor}, {"ms", t.reference_ms}}},
            {"materials", materials}};
}

Plot alpha_plot(const AlphaTune& t) {
    Plot p;
    p.title = "tune alpha: coverage error against cutoff";
    p.x_label = "alpha cutoff";
    p.y_label = "coverage error (share of the material's pixels)";
    size_t colour = 0;
    for (const AlphaMaterial& m : t.materials)
        for (bool a2c : {false, true}) {
            PlotSeries s{m.name + (a2c ? " (alpha_to_coverage)" : ""), {}, 0, true, true, {}};
            s.rgb = kPalette[colour % std::size(kPalette)];
            for (const AlphaPoint& pt : m.points)
                if (pt.alpha_to_coverage == a2c)
                    s.points.emplace_back(pt.cutoff, pt.coverage_error);
            if (s.points.empty()) continue;
            ++colour;
            p.series.push_back(std::move(s));
        }
    return p;
}

}  // namespace ds::tune
