#pragma once
// A lint report as JSON and as text. The JSON is glTF-Validator's report — "uri", "mimeType",
// "validatorVersion", "issues" {numErrors, numWarnings, numInfos, numHints, messages [{code,
// message, severity 0..3, pointer}], truncated}, "info" {counts of the asset} — with
// depthscope's fields beside it: each message's magnitude, surfaces, fix, detector and values
// (diagnose/finding_json.h), and per report the scene, the views, the settings, the depth
// configuration, the checks that ran and those skipped, the images written, the frames.
// Several scenes are an array of reports.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "capture/lint/lint.h"

namespace ds::lint {

nlohmann::json report_json(const Report& r, const scene::Scene& scene);

// The one-screen summary: per scene a head line with its counts, its findings (at most
// `max_lines`, the rest counted), the skipped checks; then a total line.
std::string reports_text(const std::vector<Report>& reports, size_t max_lines = 20);

}  // namespace ds::lint
