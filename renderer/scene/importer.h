#pragma once
// glTF 2.0 -> Scene. Files and built-in scenes (in-memory tinygltf models) take the same path,
// so both are validated alike: whatever reaches the renderer is in range and finite.
// Every failure is an InputError "SOURCE: WHAT" on one line.
#include <filesystem>
#include <map>
#include <string>

#include <tiny_gltf.h>

#include "renderer/scene/import_options.h"
#include "renderer/scene/scene.h"

namespace ds::scene {

// Converts a parsed model. `name` becomes Scene::name, `source` Scene::source and the prefix
// of error messages ("builtin:atrium", or the file path). Images must already be decoded
// (tinygltf::Image::image; 1-4 components of 8 or 16 bits).
Scene import_model(const tinygltf::Model& model, std::string name, std::string source,
                   const ImportOptions& options = {});

// Loads a .gltf or .glb file (detected by content, not by extension) and imports it.
// Scene::name is the file's stem, Scene::source the path as given.
// Every limit of import_limits.h applies; the file and each file it references must be a
// regular file (checked before anything opens it).
Scene load_gltf(const std::filesystem::path& path, const ImportOptions& options = {});

// The same from memory: `bytes` is the .gltf text or the .glb container, `files` the files its
// uris name (keys as written in the uris, decoded). `name` stands for the path in messages.
// For tests and the fuzzer; nothing touches the disk.
Scene load_gltf_memory(const std::string& bytes, const std::map<std::string, std::string>& files,
                       const std::string& name, const ImportOptions& options = {});

namespace detail {
// import_model with the images the file loader could not use (index -> why).
Scene import_parsed(const tinygltf::Model& model, std::string name, std::string source,
                    const ImportOptions& options,
                    const std::map<size_t, std::string>& image_problems);
}  // namespace detail

}  // namespace ds::scene
