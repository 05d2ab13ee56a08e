#pragma once
// A capture folder opened to render its frame again: `replay` (a new capture) and
// `view --capture` (the inspector) read it the same way, with the same checks: report.json's
// replay information (capture/replay_info.h), final.png present, the same depthscope
// version and, for a scene file, the same SHA-256 (each unless --force).
#include <filesystem>
#include <string>
#include <vector>

#include "app/cli.h"
#include "capture/replay_info.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings.h"

namespace ds::app {

struct CaptureSource {
    std::filesystem::path dir;
    std::filesystem::path report_path;  // DIR/report.json
    capture::ReplayInfo info;
    Settings settings;  // every recorded setting, then the --set overrides
};

// Reads DIR/report.json; throws ds::Error "PATH: …" (one line) for a folder that is no capture,
// a report without replay information, a missing final.png, another version without `force`,
// or a recorded setting this registry refuses; UsageError for a bad override.
CaptureSource read_capture_source(const std::filesystem::path& dir,
                                  const std::vector<std::string>& overrides, bool force);

// The scene as captured: a built-in one rebuilt with `settings`, or the file, which must be
// the one captured (the same SHA-256) unless o.force. Seen from the captured camera, or from
// the one o.camera or o.look_at choose (app/view_camera.h: against the scene's own cameras, as
// `capture` would; a bad choice throws UsageError).
scene::Scene load_captured_scene(const capture::ReplayInfo& info, const Settings& settings,
                                 const Options& o);

// The camera a capture folder's report.json recorded (its "replay" object); throws ds::Error
// "PATH: …" like read_capture_source. Its scene, version and settings are not checked.
scene::Camera captured_camera(const std::filesystem::path& dir);

// A file's bytes; throws ds::Error "PATH: cannot read".
std::string slurp(const std::filesystem::path& path);

}  // namespace ds::app
