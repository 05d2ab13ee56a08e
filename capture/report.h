#pragma once
// report.json: what was rendered, where, with which settings, and what it cost. The one place
// that turns a frame's results into JSON: capture writes frame_report(), bench's runs use
// passes_json().
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <vector>

#include <nlohmann/json.hpp>

#include "capture/advice.h"
#include "renderer/common/device_info.h"
#include "renderer/passes/frame_result.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings.h"

namespace ds::capture {

// Everything report.json says; the size and the timings are the frame's.
struct ReportInput {
    DeviceInfo device;
    const scene::Scene& scene;
    const Settings& settings;
    const FrameResult& frame;
    uint64_t validation_messages = 0;
    const Advice* advice = nullptr;  // capture --advise: report.json's `advice`
    // Captures: the camera the frame was seen from (report.json's "replay", replay_info.h)
    // and the compiled graph (Renderer::graph_json, report.json's "graph").
    const scene::Camera* camera = nullptr;
    const nlohmann::json* graph = nullptr;
};

// report.json's object.
nlohmann::json frame_report(const ReportInput& in);

// What the caller measured of passes[index], as an object merged into the pass's entry.
using PassMeasurements = std::function<nlohmann::json(size_t index)>;
// Every passes array (report.json's, each bench run's) is built here, in execution order: each
// entry says what the pass is (its name) and holds what the caller measured of it.
nlohmann::json passes_json(const std::vector<PassResult>& passes, const PassMeasurements& measured);

nlohmann::json scene_summary(const scene::Scene& scene);
// What the device's statistics (on `device`) and the exact counters mean (the report keeps
// both numbers).
nlohmann::json counters_note(const DeviceInfo& device);

// Writes pretty JSON as a new file (file_output.h: every byte checked); throws ds::Error.
void write_json(const std::filesystem::path& path, const nlohmann::json& json);
// The same onto the file an `option` (--json) names, through a temporary file renamed into
// place (write_file_atomically): PATH is complete or as it was.
void write_json_atomically(std::string_view option, const std::filesystem::path& path,
                           const nlohmann::json& json);

}  // namespace ds::capture
