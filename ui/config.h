#pragma once
// What the inspector keeps between runs, in the user's config folder
// ($DEPTHSCOPE_CONFIG_DIR, else $XDG_CONFIG_HOME/depthscope, else ~/.config/depthscope):
//   imgui.ini     the window layout (ImGui's own)
//   settings.ini  the scene and every setting that differs from its default, name=value
//   cameras.json  named camera bookmarks per scene (ui/camera_bookmarks.h), written at each change
// The command line wins over the file (--scene, --set).
#include <filesystem>
#include <string>
#include <vector>

#include "renderer/settings/settings.h"

namespace ds::ui {

std::filesystem::path config_dir();  // empty when no folder can be named
// The camera bookmarks' file in `dir` (empty when `dir` is).
std::filesystem::path bookmarks_file(const std::filesystem::path& dir);

struct SavedState {
    std::string scene;                 // "" = none saved
    std::vector<std::string> sets;     // "name=value", applied in order
    std::vector<std::string> ignored;  // lines that no longer apply (unknown knob, bad value)
};

// A missing file is an empty state. Lines are checked against the registry: what it refuses
// goes to `ignored` (the caller warns) instead of failing the start.
SavedState load_state(const std::filesystem::path& file);
// Writes atomically (temporary file + rename); throws ds::Error when the folder is unwritable.
void save_state(const std::filesystem::path& file, const std::string& scene,
                const Settings& settings);

}  // namespace ds::ui
