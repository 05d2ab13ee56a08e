#pragma once
// Builds an in-memory glTF 2.0 model the way a file would describe it: one buffer, one
// bufferView per attribute, accessors (POSITION with min/max), meshes of one primitive,
// materials, textures with decoded RGBA8 images, nodes and one scene. The importer cannot
// tell a built-in scene from a loaded file.
#include <string>
#include <string_view>

#include <tiny_gltf.h>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "renderer/scene/builtin/shapes.h"
#include "renderer/scene/builtin/textures.h"

namespace ds::scene::builtin {

enum class Alpha { Opaque, Mask, Blend };

struct MaterialSpec {
    std::string name;
    glm::vec4 base_color{1.0f};
    float metallic = 0.0f;
    float roughness = 0.8f;
    int base_color_texture = -1;  // from add_texture
    int normal_texture = -1;
    float normal_scale = 1.0f;
    glm::vec3 emissive{0.0f};
    Alpha alpha = Alpha::Opaque;
    float alpha_cutoff = 0.5f;  // written only for Mask
    bool double_sided = false;
};

// Accessor indices of one uploaded MeshData; several meshes may share them (different
// materials on the same vertices, as glTF allows).
struct Geometry {
    int position = -1;
    int normal = -1;
    int uv = -1;
    int tangent = -1;
    int indices = -1;
};

struct Transform {
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // w, x, y, z
    glm::vec3 scale{1.0f};
};

struct CameraSpec {
    float yfov = 0.9f;  // radians
    float aspect = 16.0f / 9.0f;
    float znear = 0.1f;
    float zfar = 500.0f;
};

enum class SamplerKind { Repeat, Clamp };

class ModelBuilder {
  public:
    ModelBuilder();

    Geometry add_geometry(std::string_view name, const MeshData& mesh);
    int add_mesh(std::string_view name, const Geometry& geometry, int material);
    int add_mesh(std::string_view name, const MeshData& mesh, int material);
    int add_material(const MaterialSpec& spec);
    // `name` becomes the image name and its export file name (NAME.png).
    int add_texture(std::string_view name, const Pixels& pixels,
                    SamplerKind sampler = SamplerKind::Repeat);
    int add_node(std::string_view name, int mesh, const Transform& transform = {});
    // A camera node at `eye` looking at `target` (glTF cameras look down their local -Z).
    int add_camera(std::string_view name, const CameraSpec& spec, const glm::vec3& eye,
                   const glm::vec3& target, const glm::vec3& up = {0.0f, 1.0f, 0.0f});

    // Puts every node added so far into one scene and hands the model over.
    tinygltf::Model finish(std::string_view scene_name);

  private:
    int add_view(const void* bytes, size_t size, int target);
    int add_accessor(int view, int component_type, int type, size_t count);
    int sampler(SamplerKind kind);

    tinygltf::Model model_;
    int samplers_[2] = {-1, -1};
};

// Rotation about +Y by `radians` (the most common placement in the scenes).
glm::quat yaw(float radians);

}  // namespace ds::scene::builtin
