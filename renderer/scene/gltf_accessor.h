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

// Bytes of one component (BYTE ... FLOAT); 0 for anything else.
size_t component_size(int component_type);

// Checks every buffer view and every accessor of the model, used or not.
void validate_buffer_views(const tinygltf::Model& model);
void validate_accessors(const tinygltf::Model& model);

// The component types an attribute may have, as (type, normalized) pairs.
enum class Components {
    Float,         // POSITION, NORMAL, TANGENT in core glTF
    FloatOrUnorm,  // TEXCOORD_n in core glTF: float, unsigned byte/short normalized
    // KHR_mesh_quantization (the file lists it in extensionsUsed):
    AnyInteger,  // POSITION, TEXCOORD_n: float, (unsigned) byte/short, normalized or not
    Snorm,       // NORMAL, TANGENT: float, byte/short normalized
};

struct FloatRead {
    int components = 3;  // accessor type must have exactly this many
    Components allowed = Components::Float;
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
