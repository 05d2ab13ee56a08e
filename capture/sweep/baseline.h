#pragma once
// sweep --baseline DIR (docs/sweep.md "Baseline"): this sweep against an earlier one made on the
// same device and driver, job by job (by ID). Regressions: a job that passed there and does not
// here, an exact count that changed (a capture's per-pass rasterized / shaded / discarded
// fragments, its zfight and equal_check sections; a lint's issue counts), a final.png beyond
// diff's rule (a channel off by >= threshold/255 in more than max_percent % of the pixels; SSIM
// reported beside), a baseline job this sweep lacks, another device or driver. Bench timings are
// reported, never compared.
#include <filesystem>

#include "capture/capture_diff.h"
#include "capture/sweep/sweep_summary.h"

namespace ds::capture::sweep {

// `now` as merged into `now_dir` (its jobs/ID/ folders) against the merged sweep in `base_dir`
// (its sweep.json and jobs/ID/). Throws InputError when `base_dir` holds no merged sweep.
BaselineReport compare_with_baseline(const std::vector<JobOutcome>& now,
                                     const std::filesystem::path& now_dir,
                                     const std::filesystem::path& base_dir,
                                     const DiffOptions& image_rule = {});

// What it found, one line each, for the terminal and report.md.
std::vector<std::string> baseline_lines(const BaselineReport& report,
                                        const std::vector<JobOutcome>& now);

}  // namespace ds::capture::sweep
