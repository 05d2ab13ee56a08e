#pragma once
// report.md (docs/sweep.md "Report"): a sweep in Markdown, for a CI job's artifacts or a
// merge request: the totals, one table row per job (scene, camera, settings, action, result,
// what it measured, its final.png as an image with a link relative to the sweep folder), the
// failures with their messages and the baseline comparison.
#include <string>
#include <vector>

#include "capture/sweep/sweep_summary.h"

namespace ds::capture::sweep {

std::string report_markdown(const std::vector<JobOutcome>& outcomes, const BaselineReport* baseline,
                            const std::vector<std::string>& baseline_text);

// A table cell: '|' escaped, line breaks as spaces.
std::string markdown_cell(const std::string& text);

}  // namespace ds::capture::sweep
