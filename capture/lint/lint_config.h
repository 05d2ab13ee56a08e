#pragma once
// lint --config FILE: glTF-Validator's configuration keys, in JSON —
//   "ignore": [CODE…]         codes left out (not with "only")
//   "only": [CODE…]           the only codes kept
//   "override": {CODE: SEV}   a code's severity: 0..3 or "error", "warning", "info", "hint"
//   "max-issues": N           at most N messages per report, the rest dropped with
//                             issues.truncated = true (0: no limit)
// — and depthscope's own "thresholds": {"overdraw", "mesh_overdraw", "min_steps_per_unit",
// "coverage_drop"} (lint.h's Thresholds). Codes are any UPPER_SNAKE names, so one file can
// serve glTF-Validator too; any other key, a wrong type or a value out of range is an error.
#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "capture/lint/lint.h"

namespace ds::lint {

struct Config {
    std::vector<std::string> ignore, only;
    std::map<std::string, Severity> overrides;
    size_t max_issues = 0;
    Thresholds thresholds;
};

// Throws ds::Error "FILE: why" for a file that cannot be read or is no JSON (capture::
// read_json_file), ds::InputError "FILE: why" for a bad config.
Config read_config(const std::filesystem::path& file);
Config parse_config(const nlohmann::json& j);  // throws ds::Error "why"

// Applies `c` to a report's findings: only / ignore, then the overrides, then the ranking
// again, then max-issues (setting Report::truncated).
void apply_config(const Config& c, Report& r);

}  // namespace ds::lint
