#pragma once
// A sweep's merged view (docs/sweep.md "Merge"): every job of the manifest with its result or
// "no result", as sweep.json (deterministic: no times, so that shards merged equal a
// one-process run byte for byte), JUnit XML (one testcase per job) and report.md.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "capture/sweep/jobs.h"

namespace ds::capture::sweep {

struct JobOutcome {
    Job job;
    std::optional<nlohmann::json> result;  // result.json; nullopt: no result

    // "passed", "failed" or "no result".
    std::string status() const;
    // Why it failed ("" when it passed).
    std::string message() const;
    double seconds() const;  // 0 without a result
};

// What a baseline comparison found for one job, and overall (baseline.h fills it).
struct JobComparison {
    std::vector<std::string> regressions;  // each fails the job's testcase
    std::vector<std::string> notes;        // reported only (timings, SSIM of equal images)
};
struct BaselineReport {
    std::string dir;                            // as given
    std::map<std::string, JobComparison> jobs;  // by job ID, for jobs of both sweeps
    std::vector<std::string> regressions;       // not one job's: a baseline job gone, devices
    std::vector<std::string> notes;             // new jobs the baseline lacks
    int regression_count() const;
};

// sweep.json: {"tool", "jobs": N, "passed", "failed", "no_result", "devices": [...],
// "results": [{"id", "scene", "name", "action", "status", "message"?, "device"?, "counts"?,
// "lint"?}…]} in the manifest's order.
nlohmann::json sweep_json(const std::vector<JobOutcome>& outcomes);

// JUnit XML: one <testsuite name="depthscope sweep">, a <testcase classname=SCENE name=NAME
// time=SECONDS> per job, with a <failure> when it failed, has no result or regressed against
// `baseline` (may be null).
std::string junit_xml(const std::vector<JobOutcome>& outcomes, const BaselineReport* baseline);

// `text` with &, <, >, " and ' as XML entities, and control characters other than tab, LF
// and CR (which XML 1.0 cannot hold) as '?'.
std::string xml_escaped(const std::string& text);

}  // namespace ds::capture::sweep
