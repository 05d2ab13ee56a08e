#pragma once
// report.json's "tiler": on render_path=subpass, the render pass's attachments (load, store,
// transient, memory), seed 002's tile budget (bits per pixel against 128 and 256) and merge
// conditions with the verdict, and what the path turned off; on the dynamic path, why there
// is none.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/graph/tiler.h"
#include "renderer/settings/settings.h"

namespace ds::capture {

// `turned_off`: the knobs on whose passes do not run on the path (FrameResult).
nlohmann::json tiler_json(const std::optional<graph::TilerReport>& tiler,
                          const std::vector<std::string>& turned_off, const Settings& settings);

}  // namespace ds::capture
