#pragma once
// Decoding of compressed glTF data into the placeholders gltf_prepare.h made, after tinygltf
// parsed the document and before the importer reads any accessor:
// - EXT_meshopt_compression bufferViews (Debian's meshoptimizer 0.18: the v0 vertex codec,
//   index codecs v0/v1, the OCTAHEDRAL, QUATERNION and EXPONENTIAL filters);
// - KHR_draco_mesh_compression primitives (Debian's libdraco).
// Both libraries keep their asserts or are not built with sanitizers, so every count, stride,
// mode, filter, range and index of the extension is checked before a decoder is called.
// Internal to renderer/scene; errors are InputError with a WHAT only.
#include <cstdint>
#include <map>
#include <string>

#include <tiny_gltf.h>

namespace ds::scene::detail {

// `placeholders`: the uris of buffers to fill (Prepared::placeholders); a bufferView or
// accessor in any other buffer already holds its data and is left as it is.
void decode_meshopt(tinygltf::Model& model, const std::map<std::string, uint64_t>& placeholders);
void decode_draco(tinygltf::Model& model, const std::map<std::string, uint64_t>& placeholders);

}  // namespace ds::scene::detail
