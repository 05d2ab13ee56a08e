#pragma once
// The node hierarchy of one glTF scene -> world transforms of mesh nodes, every camera node and
// the first perspective camera. Internal to renderer/scene; errors are InputError with a WHAT only.
#include <optional>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "renderer/scene/scene.h"

namespace ds::scene::detail {

struct MeshPlacement {
    int gltf_mesh = 0;
    glm::mat4 world{1.0f};
    std::string node;   // the glTF node's name, or "node N" for an unnamed one
    int gltf_node = 0;  // its index in the file's nodes
};

struct SceneWalk {
    std::vector<MeshPlacement> placements;  // depth-first, authored order
    std::vector<SceneCamera> cameras;       // every camera node met, in the same order
    std::optional<Camera> camera;           // first perspective camera placed on the way
};

// The scene to show: model.defaultScene, or scene 0 when none is set. Throws "no scene".
int pick_scene(const tinygltf::Model& model);

// Walks scene `scene_index` depth-first in authored order without recursion (deep chains
// cannot overflow the stack). Every node must be reached at most once: a cycle or a node
// with two parents throws.
SceneWalk walk_scene(const tinygltf::Model& model, int scene_index);

// Node transform from `matrix` or TRS (checked: lengths, finiteness, a usable rotation).
glm::mat4 local_transform(const tinygltf::Node& node, size_t index);

}  // namespace ds::scene::detail
