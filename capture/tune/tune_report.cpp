#include "capture/tune/tune_report.h"

#include <algorithm>
#include <cstdio>

namespace ds::tune {
namespace {

std::string format(const char* fmt, double a) {
    char buf[64];
    std::snprintf(buf, sizeof buf, fmt, a);
    return buf;
}

std::string cost_text(const Cost& c, CostKind kind) {
    if (kind == CostKind::Fragments) return std::to_string(c.shaded_fragments);
    return format("%.3f", c.frame_ms) + " (" + format("%.3f", c.frame_ms_min) + ".." +
           format("%.3f", c.frame_ms_max) + ")";
}

std::string reference_line(uint32_t factor, VkExtent2D size, double ms, uint64_t bytes) {
    return "reference: " + std::to_string(factor) + "x" + std::to_string(factor) +
           " samples per pixel at " + std::to_string(size.width) + "x" +
           std::to_string(size.height) + ", " + format("%.2f", ms / 1000.0) + " s, " +
           format("%.1f", double(bytes) / (1024.0 * 1024.0)) + " MiB read back\n";
}

nlohmann::json cost_json(const Cost& c) {
    nlohmann::json j{{"shaded_fragments", c.shaded_fragments},
                     {"discarded_fragments", c.discarded_fragments}};
    if (c.frame_ms > 0 || !c.pass_ms.empty()) {
        j["frame_ms"] = c.frame_ms;
        j["frame_ms_min"] = c.frame_ms_min;
        j["frame_ms_max"] = c.frame_ms_max;
        nlohmann::json passes = nlohmann::json::object();
        for (const auto& [name, ms] : c.pass_ms) passes[name] = ms;
        j["pass_ms"] = passes;
    }
    return j;
}

const char* cost_unit(CostKind kind) {
    return kind == CostKind::Ms ? "frame GPU ms, median (min..max)" : "shaded fragments";
}

}  // namespace

std::string assignments_text(const std::vector<std::string>& assignments) {
    std::string s;
    for (const std::string& a : assignments) s += (s.empty() ? "" : " ") + a;
    return s;
}

std::string msaa_text(const MsaaTune& t) {
    std::string s = reference_line(t.reference_factor, t.size, t.reference_ms, t.reference_bytes);
    s += "edge pixels: " + std::to_string(t.edge_pixels) + "\n";
    char line[256];
    std::snprintf(line, sizeof line, "%-42s %8s %10s  %s\n", "candidate", "SSIM", "edge error",
                  cost_unit(t.cost_kind));
    s += line;
    for (const MsaaRow& r : t.rows) {
        std::snprintf(line, sizeof line, "%-42s %8.5f %10.4f  %s%s\n", r.candidate.label().c_str(),
                      r.score.ssim, r.score.edge_error, cost_text(r.cost, t.cost_kind).c_str(),
                      r.front ? "  front" : "");
        s += line;
    }
    for (const Recommendation& rec : t.recommendations) {
        const std::string budget =
            rec.budget > 0 ? "within " + format("%.1f", rec.budget) + "x the cheapest" : "any cost";
        s += "recommended (" + budget + "): " +
             (rec.row < 0 ? std::string("none")
                          : assignments_text(t.rows[size_t(rec.row)].candidate.assignments())) +
             "\n";
    }
    return s;
}

nlohmann::json msaa_json(const MsaaTune& t) {
    nlohmann::json rows = nlohmann::json::array();
    for (const MsaaRow& r : t.rows)
        rows.push_back({{"label", r.candidate.label()},
                        {"msaa", r.candidate.msaa},
                        {"sample_shading", r.candidate.sample_shading},
                        {"alpha_to_coverage", r.candidate.alpha_to_coverage},
                        {"ssim", r.score.ssim},
                        {"edge_error", r.score.edge_error},
                        {"percent_over", r.score.percent_over},
                        {"cost", cost_json(r.cost)},
                        {"front", r.front}});
    nlohmann::json recs = nlohmann::json::array();
    for (const Recommendation& rec : t.recommendations)
        recs.push_back(
            {{"budget_x_cheapest", rec.budget},
             {"candidate", rec.row < 0 ? nlohmann::json() : nlohmann::json(rec.row)},
             {"set", rec.row < 0
                         ? nlohmann::json::array()
                         : nlohmann::json(t.rows[size_t(rec.row)].candidate.assignments())}});
    return {{"size", {t.size.width, t.size.height}},
            {"cost", cost_kind_name(t.cost_kind)},
            {"reference",
             {{"factor", t.reference_factor},
              {"ms", t.reference_ms},
              {"readback_bytes", t.reference_bytes},
              {"edge_pixels", t.edge_pixels}}},
            {"candidates", rows},
            {"recommendations", recs}};
}

Plot msaa_plot(const MsaaTune& t) {
    Plot p;
    p.title = "tune msaa: edge error against cost";
    p.x_label = cost_unit(t.cost_kind);
    p.y_label = "edge error (mean luma, of 255)";
    PlotSeries all{"candidates", {}, 0x3a6fd8, false, true, {}};
    PlotSeries front{"Pareto front", {}, 0xd8553a, true, true, {}};
    for (const MsaaRow& r : t.rows) {
        const std::pair<double, double> xy{r.cost.value(t.cost_kind), r.score.error()};
        const std::string label = r.candidate.label().substr(5);  // "msaa " left out
        // Candidates that score and cost the same (alpha_to_coverage without MASK materials)
        // share one marker and one label.
        const auto same = std::find(all.points.begin(), all.points.end(), xy);
        if (same != all.points.end()) {
            all.point_labels[size_t(same - all.points.begin())] += " | " + label;
        } else {
            all.points.push_back(xy);
            all.point_labels.push_back(label);
        }
        if (r.front &&
            std::find(front.points.begin(), front.points.end(), xy) == front.points.end())
            front.points.push_back(xy);
    }
    std::sort(front.points.begin(), front.points.end());
    p.series = {all, front};
    return p;
}

}  // namespace ds::tune
