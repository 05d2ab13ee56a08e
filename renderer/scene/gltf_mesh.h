#pragma once
// glTF meshes -> Scene meshes: one Scene Mesh per triangle primitive. Internal to
// renderer/scene; errors are InputError with a WHAT only.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "renderer/scene/scene.h"

namespace ds::scene::detail {

struct MeshImport {
    // Scene mesh indices of each glTF mesh's triangle primitives, in primitive order.
    std::vector<std::vector<uint32_t>> by_gltf_mesh;
    std::map<std::string, uint32_t> skipped_modes;  // "LINES" -> number of primitives skipped
    bool uses_default_material = false;
};

// Appends a Mesh to `meshes` for every triangle primitive of every glTF mesh. Primitives
// without a material get `default_material` (the caller appends that material when
// uses_default_material is set).
MeshImport import_meshes(const tinygltf::Model& model, uint32_t default_material,
                         std::vector<Mesh>& meshes);

}  // namespace ds::scene::detail
