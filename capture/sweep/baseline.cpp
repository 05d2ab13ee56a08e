#include "capture/sweep/baseline.h"

#include <cstdio>
#include <set>

#include "capture/capture_folder.h"
#include "capture/sweep/job_result.h"
#include "capture/sweep/sweep_files.h"
#include "renderer/common/error.h"
#include "renderer/common/quoted.h"

namespace fs = std::filesystem;
using nlohmann::json;

namespace ds::capture::sweep {
namespace {

std::string number_text(double value, const char* format) {
    char text[48];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

// final.png of both: regression beyond diff's rule, else a note when any pixel differs.
void compare_images(const fs::path& base, const fs::path& now, const DiffOptions& rule,
                    JobComparison& c) {
    std::error_code ec;
    if (!fs::is_regular_file(base, ec) || !fs::is_regular_file(now, ec)) return;
    const Rgba8Image a = read_png_rgba8(base), b = read_png_rgba8(now);
    if (a.width != b.width || a.height != b.height) {
        c.regressions.push_back("final.png " + std::to_string(a.width) + "x" +
                                std::to_string(a.height) + " -> " + std::to_string(b.width) + "x" +
                                std::to_string(b.height));
        return;
    }
    const ImageDiff d = diff_final(a, b, rule.threshold);
    if (d.differing == 0) return;
    const std::optional<double> ssim = final_ssim(a, b);
    const std::string line = "final.png: " + number_text(d.percent(), "%.3f") +
                             " % of the pixels differ by >= " + std::to_string(rule.threshold) +
                             "/255 (at most " + number_text(rule.max_percent, "%g") + " % pass)" +
                             (ssim ? ", SSIM " + number_text(*ssim, "%.4f") : "");
    (d.percent() > rule.max_percent ? c.regressions : c.notes).push_back(line);
}

// A bench's frame time, baseline -> now (never a regression).
void compare_timings(const json& base, const json& now, JobComparison& c) {
    const auto median = [](const json& r) -> std::optional<double> {
        if (!r.contains("timings")) return std::nullopt;
        return r.at("timings").at("frame_ms").value("median", 0.0);
    };
    const std::optional<double> a = median(base), b = median(now);
    if (!a || !b) return;
    c.notes.push_back("frame ms (median) " + number_text(*a, "%.3f") + " -> " +
                      number_text(*b, "%.3f") +
                      (*a > 0 ? " (x" + number_text(*b / *a, "%.2f") + ")" : ""));
}

JobComparison compare_job(const json& base_summary, const JobOutcome& now, const fs::path& now_dir,
                          const fs::path& base_dir, const DiffOptions& rule) {
    JobComparison c;
    const std::string was = base_summary.value("status", "?");
    if (was == "passed" && now.status() != "passed")
        c.regressions.push_back("passed in the baseline, now " + now.status());
    if (was != "passed" && now.status() == "passed")
        c.notes.push_back("was " + was + ", now passed");
    if (!now.result || !now.result->contains("status")) return c;
    for (const char* key : {"counts", "lint"}) {
        if (!base_summary.contains(key) && !now.result->contains(key)) continue;
        const json a = base_summary.value(key, json()), b = now.result->value(key, json());
        for (const std::string& d : json_differences(a, b, key)) c.regressions.push_back(d);
    }
    const fs::path base_job = job_dir(base_dir, now.job.id), now_job = job_dir(now_dir, now.job.id);
    if (now.job.action.kind == ActionKind::Capture)
        compare_images(base_job / "capture" / "final.png", now_job / "capture" / "final.png", rule,
                       c);
    if (now.job.action.kind == ActionKind::Bench) {
        const std::optional<json> base_result = read_job_result(base_dir, now.job.id);
        if (base_result) compare_timings(*base_result, *now.result, c);
    }
    return c;
}

void compare_devices(const json& base, const std::vector<JobOutcome>& now, BaselineReport& r) {
    const json devices = sweep_json(now).at("devices");
    const json was = base.value("devices", json::array());
    if (!was.empty() && !devices.empty() && was != devices)
        r.regressions.push_back("the baseline ran on " + was.dump() + ", this sweep on " +
                                devices.dump() + ": exact counts compare on one device and driver");
}

}  // namespace

BaselineReport compare_with_baseline(const std::vector<JobOutcome>& now, const fs::path& now_dir,
                                     const fs::path& base_dir, const DiffOptions& rule) {
    const json base = read_json_file(base_dir / "sweep.json");
    if (!base.is_object() || !base.contains("results") || !base.at("results").is_array())
        throw InputError(escaped((base_dir / "sweep.json").string()) + ": not a merged sweep");
    BaselineReport report;
    report.dir = base_dir.string();
    compare_devices(base, now, report);
    std::map<std::string, json> by_id;
    for (const json& r : base.at("results")) by_id[r.value("id", "")] = r;
    std::set<std::string> ids;
    for (const JobOutcome& o : now) {
        ids.insert(o.job.id);
        const auto it = by_id.find(o.job.id);
        if (it == by_id.end()) {
            report.notes.push_back("new job, not in the baseline: " + o.job.scene + " · " +
                                   o.job.name());
            continue;
        }
        report.jobs[o.job.id] = compare_job(it->second, o, now_dir, base_dir, rule);
    }
    for (const auto& [id, r] : by_id)
        if (!ids.count(id))
            report.regressions.push_back(
                "baseline job not in this sweep: " + r.value("scene", "?") + " · " +
                r.value("name", "?") + " (" + id + ")");
    return report;
}

std::vector<std::string> baseline_lines(const BaselineReport& report,
                                        const std::vector<JobOutcome>& now) {
    std::vector<std::string> lines;
    for (const std::string& r : report.regressions) lines.push_back("regression: " + r);
    for (const JobOutcome& o : now) {
        if (!report.jobs.count(o.job.id)) continue;
        const JobComparison& c = report.jobs.at(o.job.id);
        const std::string who = o.job.scene + " · " + o.job.name() + ": ";
        for (const std::string& r : c.regressions) lines.push_back("regression: " + who + r);
        for (const std::string& n : c.notes) lines.push_back("note: " + who + n);
    }
    for (const std::string& n : report.notes) lines.push_back("note: " + n);
    return lines;
}

}  // namespace ds::capture::sweep
