#pragma once
// One job's result.json (docs/sweep.md "Results"): how its process ended, and what of its
// action's output a sweep compares: a capture's exact counts (report.json: each pass's
// rasterized, shaded and discarded fragments, the zfight and equal_check sections) and device,
// a bench's timings, a lint's issue counts.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "capture/sweep/jobs.h"

namespace ds::capture::sweep {

// How the job's process ended.
struct ChildExit {
    int exit_code = -1;  // when it exited
    int signal = 0;      // when a signal ended it
    double seconds = 0;  // wall time
};

// result.json for `job`, whose outputs (and log.txt) are in `dir`. "status" is "passed" when
// the process exited 0 and its output is readable, else "failed" with a "message" (the
// process's error line, or what is wrong with its output).
nlohmann::json job_result(const Job& job, const ChildExit& exit, const std::filesystem::path& dir);

// A capture's counts from its report.json: {"passes": {NAME: {rasterized_fragments, …}},
// "zfight": …, "equal_check": …}, each part only where the report has it.
nlohmann::json report_counts(const nlohmann::json& report);

// The path of every leaf that differs between two JSON values ("passes.forward.
// shaded_fragments: 857 -> 900"; a key in one only: "… absent -> 3").
std::vector<std::string> json_differences(const nlohmann::json& a, const nlohmann::json& b,
                                          const std::string& path = "");

}  // namespace ds::capture::sweep
