#pragma once
// Test-side reading of a tinygltf model: accessors, the node hierarchy flattened into world
// triangles, and the scene's camera. Independent of the renderer's importer on purpose, so the
// built-in scenes are checked against the glTF spec, not against the importer.
#include <cstdint>
#include <optional>
#include <vector>

#include <tiny_gltf.h>
#include <glm/glm.hpp>

namespace ds::test {

std::vector<glm::vec3> read_vec3(const tinygltf::Model& m, int accessor);
std::vector<uint32_t> read_indices(const tinygltf::Model& m, int accessor);

struct WorldTriangle {
    glm::vec3 p[3];
    int material = -1;
    int mesh = -1;
    int node = -1;
    bool double_sided = false;
};

glm::mat4 node_local_matrix(const tinygltf::Node& node);
// World matrix of every node (identity for nodes not reachable from the default scene).
std::vector<glm::mat4> world_matrices(const tinygltf::Model& m);
std::vector<WorldTriangle> world_triangles(const tinygltf::Model& m);

struct ViewCamera {
    glm::mat4 view{1.0f};  // world -> camera (camera looks down -Z)
    float yfov = 0.8f;
    float aspect = 16.0f / 9.0f;
    float znear = 0.1f;
    float zfar = 1000.0f;
};
// The first node with a perspective camera, in node order.
std::optional<ViewCamera> find_camera(const tinygltf::Model& m);
ViewCamera look_at(const glm::vec3& eye, const glm::vec3& target, float yfov, float aspect);

}  // namespace ds::test
