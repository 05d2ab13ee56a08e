#pragma once
// The scene model: what the renderer draws. Produced only by the glTF importer (files and
// built-in scenes both go through it), consumed by the renderer. No Vulkan here.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/common/surface_name.h"

namespace ds::scene {

enum class AlphaMode : uint8_t { Opaque, Mask, Blend };
const char* to_string(AlphaMode mode);

// Interleaved vertex as uploaded to the GPU (48 bytes).
struct Vertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    glm::vec2 uv0{0.0f};
    glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f};  // xyz tangent, w handedness
};
static_assert(sizeof(Vertex) == 48);

struct Bounds {
    glm::vec3 min{1e30f};
    glm::vec3 max{-1e30f};
    bool valid() const { return min.x <= max.x && min.y <= max.y && min.z <= max.z; }
    void extend(const glm::vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void extend(const Bounds& b) {
        if (b.valid()) {
            extend(b.min);
            extend(b.max);
        }
    }
    glm::vec3 center() const { return (min + max) * 0.5f; }
    glm::vec3 extent() const { return max - min; }
};

// One glTF primitive (triangles, one material). glTF meshes with several primitives become
// several Meshes; `gltf_mesh` keeps the original index.
struct Mesh {
    std::string name;
    uint32_t gltf_mesh = 0;
    uint32_t material =
        0;  // index into Scene::materials (a default material is appended if needed)
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;  // always present (generated 0..n-1 when the file has none)
    Bounds bounds;                  // object space
};

// Decoded image, always RGBA8. `srgb` is true when a material uses it as base colour or
// emissive (colour data); otherwise it holds linear data (normals, metallic-roughness, AO).
struct Image {
    std::string name;
    uint32_t width = 0;
    uint32_t height = 0;
    bool srgb = false;
    std::vector<uint8_t> rgba8;
};

enum class Filter : uint8_t { Nearest, Linear };
enum class Wrap : uint8_t { Repeat, ClampToEdge, MirroredRepeat };

struct Sampler {
    Filter mag = Filter::Linear;
    Filter min = Filter::Linear;
    bool mipmaps = true;  // minFilter uses mipmaps
    Filter mip = Filter::Linear;
    Wrap wrap_s = Wrap::Repeat;
    Wrap wrap_t = Wrap::Repeat;
};

struct Texture {
    uint32_t image = 0;
    uint32_t sampler = 0;  // index into Scene::samplers (a default sampler is always at the end)
};

struct TextureRef {
    int32_t texture = -1;  // -1: none
    uint32_t uv_set = 0;   // only set 0 is supported by the renderer
    // KHR_texture_transform: uv' = offset + rotate(rotation) * (scale * uv).
    glm::vec2 offset{0.0f};
    float rotation = 0.0f;  // radians, counter-clockwise in UV space
    glm::vec2 scale{1.0f};
    bool present() const { return texture >= 0; }
    // The transform as two rows (a, b, tx) and (c, d, ty): u' = a u + b v + tx, ...
    std::array<glm::vec3, 2> uv_rows() const;
};

struct Material {
    std::string name;
    glm::vec4 base_color_factor{1.0f};
    float metallic_factor = 1.0f;
    float roughness_factor = 1.0f;
    glm::vec3 emissive_factor{0.0f};
    float normal_scale = 1.0f;
    float occlusion_strength = 1.0f;
    TextureRef base_color;
    TextureRef metallic_roughness;
    TextureRef normal;
    TextureRef occlusion;
    TextureRef emissive;
    AlphaMode alpha_mode = AlphaMode::Opaque;
    float alpha_cutoff = 0.5f;
    bool double_sided = false;
};

// One placement of a Mesh in the world (from the node hierarchy).
struct Instance {
    uint32_t mesh = 0;
    glm::mat4 world{1.0f};
    std::string node;    // the node that places it (glTF name, or "node N"), for reports
    int gltf_node = -1;  // that node's index in the glTF (built-ins: in export-scene's file)
};

// Instances that share (mesh, alpha mode, double-sided, decal): drawn with one instanced draw
// (seed 000). Instances of a group are contiguous in Scene::instances. Groups keep the order
// in which the file first uses them (authored order, never sorted front to back).
struct DrawGroup {
    uint32_t mesh = 0;
    AlphaMode alpha_mode = AlphaMode::Opaque;
    bool double_sided = false;
    uint32_t first_instance = 0;
    uint32_t instance_count = 0;
    // Its instances are coplanar overlays (Scene::decals; decals.h). Last, so positional
    // initialisers written before it still mean what they said.
    bool decal = false;
};

// A coplanar overlay (seed 004: Sponza's layered meshes, the same vertices as the wall under
// them) and the surface it lies on, both indices into Scene::instances. Found by geometry at
// load, whatever the renderer's settings (decals.h).
struct Decal {
    uint32_t instance = 0;  // the overlay
    uint32_t base = 0;      // the instance it lies on (never itself a decal)
};

// A surface hidden just behind another that faces the same way, by a gap a depth test
// resolves (decals.h: a buried overlay, such as a decal a compressor moved off its wall); both
// indices into Scene::instances.
struct BuriedOverlay {
    uint32_t instance = 0;  // the hidden one
    uint32_t base = 0;      // the surface in front of it
    double gap = 0.0;       // scene units
};

struct Camera {
    glm::vec3 position{0.0f, 0.0f, 5.0f};
    glm::vec3 forward{0.0f, 0.0f, -1.0f};  // unit
    glm::vec3 up{0.0f, 1.0f, 0.0f};        // unit
    float yfov = 0.8f;                     // radians
    float znear = 0.1f;
    float zfar = 1000.0f;
    glm::mat4 view() const;
    bool operator==(const Camera&) const = default;  // the same view, bit for bit
};

// A camera node of the glTF scene shown (every one the node walk meets, in its depth-first
// authored order): what `depthscope cameras` lists and `--camera NAME|INDEX` picks.
struct SceneCamera {
    enum class Type : uint8_t { Perspective, Orthographic };
    int gltf_node = -1;  // its index in the file's nodes (built-ins: in export-scene's file)
    std::string name;    // the node's name, "" when it has none
    Type type = Type::Perspective;
    float yfov = 0.0f;  // radians (perspective; 0 for an orthographic camera)
    float znear = 0.0f;
    float zfar = 0.0f;  // 0: none given (a perspective camera's infinite far plane)
    // Placed at its node, perspective only (zfar then finite, as Scene::camera's); none for an
    // orthographic camera or a node whose transform leaves no view direction (zero scale).
    std::optional<Camera> camera;
};
const char* to_string(SceneCamera::Type type);

struct DirectionalLight {
    glm::vec3 direction{-0.3f, -1.0f, -0.4f};  // direction the light travels (unit)
    glm::vec3 color{1.0f};
    float intensity = 3.0f;
};

struct Scene {
    std::string name;    // "atrium", or the file's stem
    std::string source;  // "builtin:atrium" or the file path
    uint32_t gltf_mesh_count = 0;
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<Image> images;
    std::vector<Sampler> samplers;
    std::vector<Texture> textures;
    std::vector<Instance> instances;
    std::vector<DrawGroup> draw_groups;
    std::vector<Decal> decals;          // sorted by instance; exactly the instances of decal groups
    std::vector<BuriedOverlay> buried;  // sorted by instance
    Bounds bounds;                      // world space
    std::vector<SceneCamera> cameras;   // every camera node, in walk order
    std::optional<Camera> file_camera;  // the first perspective one placed, when there is one
    Camera camera;                      // file_camera, or framed from the bounds
    DirectionalLight sun;
    std::vector<std::string> warnings;  // import notes, one line each (skipped primitives ...)

    uint64_t triangle_count() const;  // over all instances
    // An instance's material, and how reports name it: its mesh, material and node.
    const Material& instance_material(uint32_t instance) const;
    SurfaceName instance_name(uint32_t instance) const;
};

// Camera that looks at `bounds` from a pleasant direction with the whole box in view.
Camera frame_bounds(const Bounds& bounds, float yfov = 0.8f);

// What a camera should frame (the inspector's F, its orbit centre and fly speed): the world
// box of the scene's instances without the few largest that dwarf the rest — a ground plane,
// a backdrop, a sky dome. Sorted by size, the k largest instances are left out for the
// smallest k (at most max(2, n/10), never all) that leaves a box whose diagonal is at most
// 1/kContentDwarf of the whole; without such a k, the whole bounds.
inline constexpr float kContentDwarf = 2.5f;
Bounds content_bounds(const Scene& scene);

}  // namespace ds::scene
