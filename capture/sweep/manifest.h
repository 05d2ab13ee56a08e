#pragma once
// `depthscope sweep`'s manifest (docs/sweep.md): scenes x cameras x setting sets x actions, read
// from JSON and checked whole before any job runs. Every unknown key and every bad value is an
// InputError "MANIFEST: KEY: WHY" naming the key by its JSON path (`settings[1].msaa`).
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace ds::capture::sweep {

// A setting set: knob name -> canonical value (Settings::set's text), sorted by name.
using SettingSet = std::map<std::string, std::string>;

struct SceneSpec {
    std::string given;           // as the manifest writes it ("atrium", "models/a.gltf")
    bool builtin = false;        // a built-in scene's name
    std::filesystem::path path;  // a file: resolved against the manifest's folder
};

// The view: both empty is the scene's camera; else exactly one (--camera, --look-at).
struct CameraSpec {
    std::string camera;   // NAME or INDEX
    std::string look_at;  // "EX,EY,EZ:TX,TY,TZ[:FOV]"
    bool operator==(const CameraSpec&) const = default;
};

enum class ActionKind { Capture, Bench, Lint };
const char* action_name(ActionKind kind);  // "capture", "bench", "lint"

struct ActionSpec {
    ActionKind kind = ActionKind::Capture;
    std::string resources = "none";     // capture --resources
    int frames = 5, warmup = 1;         // bench --frames, --warmup
    std::string fail_on;                // lint --fail-on ("": lint's default)
    std::string config;                 // lint --config, as given ("" none)
    std::filesystem::path config_path;  // resolved against the manifest's folder
};

struct Manifest {
    std::filesystem::path file;  // as given
    nlohmann::json source;       // the parsed document
    std::vector<SceneSpec> scenes;
    std::vector<CameraSpec> cameras;   // at least the scene's camera
    std::vector<SettingSet> settings;  // common_settings merged in; at least one (empty) set
    std::vector<ActionSpec> actions;
    std::string size = "1280x720";  // checked by the caller (app's parse_size)
    bool validate = false;
};

// Reads and checks the manifest at `file`. Throws InputError naming the file and the key.
Manifest read_manifest(const std::filesystem::path& file);
// The same from text already read (`file` names it in messages and anchors relative paths).
Manifest parse_manifest(std::string_view text, const std::filesystem::path& file);

}  // namespace ds::capture::sweep
