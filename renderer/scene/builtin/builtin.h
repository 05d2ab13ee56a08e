#pragma once
// Built-in scenes, built in code as in-memory glTF models (textures generated in code). They go
// through the same importer as files, so a built-in scene and its exported .gltf load alike.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <tiny_gltf.h>

#include "renderer/settings/settings.h"

namespace ds::scene::builtin {

struct Info {
    std::string name;
    std::string description;  // one line
};

// In the order `depthscope scenes` prints them; the first is the default scene.
const std::vector<Info>& list();
bool exists(std::string_view name);

// Builds the named scene. Knobs such as overdraw_layers come from `settings`.
// Throws UsageError for an unknown name (listing the valid ones).
tinygltf::Model build(std::string_view name, const Settings& settings);

// Writes `model` as OUT.gltf + OUT.bin + one PNG per image beside it, so that loading OUT.gltf
// gives the same scene. Nothing is left behind on failure (throws ds::Error).
void export_model(const tinygltf::Model& model, const std::filesystem::path& out_gltf);

}  // namespace ds::scene::builtin
