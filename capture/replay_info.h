#pragma once
// What report.json holds so that `depthscope replay` can render the frame again
// (report.json's "version" and "replay"): the scene's source (a built-in name and the knobs
// that shape it, or a file's absolute path and SHA-256), the camera exactly (floats survive a
// JSON double round trip), the size; the settings are report.json's "settings" (every knob).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "renderer/scene/scene.h"
#include "renderer/settings/settings.h"

namespace ds::capture {

// A camera as report.json's replay.camera holds it (floats survive the JSON round trip), and
// back: nothing, or what is wrong ("position is not three numbers"). Camera bookmarks share it.
nlohmann::json camera_json(const scene::Camera& camera);
std::optional<std::string> read_camera(const nlohmann::json& c, scene::Camera& out);

// report.json's "replay" object for a frame of `scene` seen by `camera`.
nlohmann::json replay_json(const scene::Scene& scene, const scene::Camera& camera,
                           const Settings& settings);

// Read back from a capture's report.json.
struct ReplayInfo {
    std::string version;         // of the depthscope that captured it
    std::string builtin;         // a built-in scene's name, or ""
    std::filesystem::path file;  // else the scene file
    std::string sha256;          // the file's digest at capture time
    scene::Camera camera;
    uint32_t width = 0, height = 0;
    std::vector<std::string> settings;  // "name=value", every knob recorded
};

// Throws ds::Error "REPORT: …" when the report lacks what a replay needs, or holds it in
// another form (a report of an older depthscope without "replay").
ReplayInfo parse_replay(const nlohmann::json& report, const std::filesystem::path& report_path);

}  // namespace ds::capture
