#pragma once
// Bounds-checked reading of glTF buffer views and accessors. Every byte read is checked against
// the bytes that are really in the buffer (never the declared byteLength alone).
// Internal to renderer/scene; errors are InputError with a WHAT only (see import_util.h).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace ds::scene::detail {

// Checks every buffer view and every accessor of the model, used or not.
void validate_buffer_views(const tinygltf::Model& model);
void validate_accessors(const tinygltf::Model& model);

struct FloatRead {
    int components = 3;                  // accessor type must have exactly this many
    bool allow_normalized_ints = false;  // unsigned byte/short normalized (TEXCOORD_n)
};

// Accessor `index` as count × components floats (sparse substitutions applied); any NaN/Inf
// throws. `what` names the use in messages, e.g. "mesh 0 primitive 1 POSITION".
std::vector<float> read_floats(const tinygltf::Model& model, int index, const FloatRead& spec,
                               const std::string& what);

// Accessor `index` as indices (SCALAR unsigned byte/short/int).
std::vector<uint32_t> read_indices(const tinygltf::Model& model, int index,
                                   const std::string& what);

// Number of elements of accessor `index` (checked).
size_t accessor_count(const tinygltf::Model& model, int index, const std::string& what);

}  // namespace ds::scene::detail
