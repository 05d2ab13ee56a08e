#pragma once
// A Diagnosis as JSON (for CI, `diagnose --json`) and as a one-screen text summary.
// The JSON follows glTF-Validator's report: "issues" {numErrors, numWarnings, numInfos,
// numHints, messages [{code, message, severity (0..3), pointer}], truncated}, each message
// with depthscope's fields (magnitude {value, unit}, surfaces [{mesh, material, node,
// pointer}], fix, detector); beside it what it ran on (scene, camera, size, settings), the
// measurement knobs it added, the detectors that ran, those skipped [{detector, reason}] and
// the frames it rendered. A finding's pixels are not written.
#include <string>

#include <nlohmann/json.hpp>

#include "capture/diagnose/finding.h"

namespace ds::diagnose {

nlohmann::json finding_json(const Finding& f);
// A camera as reports write it: position, forward, up, yfov, znear, zfar.
nlohmann::json camera_json(const scene::Camera& c);
nlohmann::json diagnosis_json(const Diagnosis& d);

// The ranked findings ("error EQUAL_HOLES 21,682 px: …" and its fix), then the skipped
// detectors ("skipped: equal_check (depth_compare is not equal)") and a count line.
std::string diagnosis_text(const Diagnosis& d);

// 1234567 -> "1,234,567"; a fraction keeps up to 2 decimals ("2.41").
std::string grouped(double value);

}  // namespace ds::diagnose
