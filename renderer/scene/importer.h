#pragma once
// glTF 2.0 -> Scene. Files and built-in scenes (in-memory tinygltf models) take the same path,
// so both are validated alike: whatever reaches the renderer is in range and finite.
// Every failure is an InputError "SOURCE: WHAT" on one line.
#include <filesystem>
#include <string>

#include <tiny_gltf.h>

#include "renderer/scene/scene.h"

namespace ds::scene {

// Converts a parsed model. `name` becomes Scene::name, `source` Scene::source and the prefix
// of error messages ("builtin:atrium", or the file path). Images must already be decoded
// (tinygltf::Image::image; 1-4 components of 8 or 16 bits).
Scene import_model(const tinygltf::Model& model, std::string name, std::string source);

// Loads a .gltf or .glb file (detected by content, not by extension) and imports it.
// Scene::name is the file's stem, Scene::source the path as given.
Scene load_gltf(const std::filesystem::path& path);

}  // namespace ds::scene
