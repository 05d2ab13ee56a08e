#pragma once
// A frame's measurements as JSON, shared by `capture` (report.json) and `bench`.
#include <nlohmann/json.hpp>

#include "renderer/renderer.h"

namespace ds::app {

// [{"name", "gpu_ms", "stats": {...}, "shaded_fragments"?}] in execution order.
nlohmann::json passes_json(const FrameResult& frame);
// What the device's statistics and the exact counters mean (the report keeps both numbers).
nlohmann::json counters_note();

}  // namespace ds::app
