#include "capture/sweep/sweep_report.h"

#include <cstdio>

namespace ds::capture::sweep {
namespace {

using nlohmann::json;

std::string decimal_text(double value, const char* format) {
    char text[48];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

// What the job measured, in a few words.
std::string details(const JobOutcome& o) {
    if (!o.result) return "";
    const json& r = *o.result;
    std::string out;
    if (r.contains("counts") && r.at("counts").contains("passes")) {
        uint64_t shaded = 0, rasterized = 0;
        for (const auto& [name, pass] : r.at("counts").at("passes").items()) {
            shaded += pass.value("shaded_fragments", uint64_t(0));
            rasterized += pass.value("rasterized_fragments", uint64_t(0));
        }
        out += "shaded " + std::to_string(shaded) + ", rasterized " + std::to_string(rasterized);
    }
    if (r.contains("counts") && r.at("counts").contains("zfight"))
        out += std::string(out.empty() ? "" : "; ") + "zfight " +
               std::to_string(r.at("counts").at("zfight").value("pixels", uint64_t(0))) + " px";
    if (r.contains("timings"))
        out += "frame " +
               decimal_text(r.at("timings").at("frame_ms").value("median", 0.0), "%.2f") +
               " ms (median)";
    if (r.contains("lint"))
        out += std::to_string(r.at("lint").value("numErrors", 0)) + " errors, " +
               std::to_string(r.at("lint").value("numWarnings", 0)) + " warnings";
    return out;
}

std::string image_cell(const JobOutcome& o) {
    if (!o.result || !o.result->contains("outputs") || !o.result->at("outputs").contains("final"))
        return "";
    const std::string link =
        "jobs/" + o.job.id + "/" + o.result->at("outputs").at("final").get<std::string>();
    return "[![" + markdown_cell(o.job.name()) + "](" + link + ")](" + link + ")";
}

std::string totals(const std::vector<JobOutcome>& outcomes) {
    const json summary = sweep_json(outcomes);
    std::string out = std::to_string(outcomes.size()) +
                      " jobs: " + std::to_string(summary.at("passed").get<int>()) + " passed, " +
                      std::to_string(summary.at("failed").get<int>()) + " failed, " +
                      std::to_string(summary.at("no_result").get<int>()) + " without a result.";
    for (const json& d : summary.at("devices"))
        out += " Device: " + d.value("name", "?") + " (" + d.value("driver", "?") + ").";
    return out + "\n";
}

std::string table(const std::vector<JobOutcome>& outcomes) {
    std::string md =
        "| Scene | Camera | Settings | Action | Result | Seconds | Measured | Final |\n"
        "|---|---|---|---|---|---:|---|---|\n";
    for (const JobOutcome& o : outcomes) {
        md += "| " + markdown_cell(o.job.scene) + " | " + markdown_cell(o.job.camera_label()) +
              " | " + markdown_cell(o.job.settings_label()) + " | " +
              action_name(o.job.action.kind) + " | " + o.status() + " | " +
              (o.result ? decimal_text(o.seconds(), "%.1f") : "") + " | " +
              markdown_cell(details(o)) + " | " + image_cell(o) + " |\n";
    }
    return md;
}

}  // namespace

std::string report_markdown(const std::vector<JobOutcome>& outcomes, const BaselineReport* baseline,
                            const std::vector<std::string>& baseline_text) {
    std::string md = "# depthscope sweep\n\n" + totals(outcomes) + "\n" + table(outcomes);
    std::string failures;
    for (const JobOutcome& o : outcomes)
        if (o.status() != "passed")
            failures += "- **" + markdown_cell(o.job.scene + " · " + o.job.name()) + "** (" +
                        o.job.id + "): " + markdown_cell(o.message()) + "\n";
    if (!failures.empty()) md += "\n## Failures\n\n" + failures;
    if (baseline) {
        md += "\n## Baseline: " + markdown_cell(baseline->dir) + "\n\n" +
              std::to_string(baseline->regression_count()) + " regressions.\n\n";
        for (const std::string& line : baseline_text) md += "- " + markdown_cell(line) + "\n";
    }
    return md;
}

std::string markdown_cell(const std::string& text) {
    std::string out;
    for (const char c : text) {
        if (c == '|')
            out += "\\|";
        else if (c == '\n' || c == '\r')
            out += ' ';
        else
            out += c;
    }
    return out;
}

}  // namespace ds::capture::sweep
