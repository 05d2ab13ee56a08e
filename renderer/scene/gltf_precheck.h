#pragma once
// Checks of a glTF file's raw JSON, made before tinygltf parses it. tinygltf silently drops
// values of the wrong type (a `"name": 42`, an array where an object belongs, an index of -1)
// and reads glTF 1.0 files as empty 2.0 models; these checks turn both into clear errors.
// Internal to renderer/scene; errors are InputError with a WHAT only.
#include <string_view>

namespace ds::scene::detail {

// `bytes` is the whole file; `binary` when it starts with the GLB magic "glTF".
// Checks, in order: GLB header, JSON syntax, asset.version (2.x), extensionsRequired
// (supported or ignorable), then the JSON types of the core glTF properties.
void precheck_gltf(std::string_view bytes, bool binary);

}  // namespace ds::scene::detail
