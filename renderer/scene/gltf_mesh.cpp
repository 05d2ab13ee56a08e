#include "renderer/scene/gltf_mesh.h"

#include <algorithm>

#include "renderer/scene/gltf_accessor.h"
#include "renderer/scene/import_util.h"
#include "renderer/scene/mesh_ops.h"

namespace ds::scene::detail {
namespace {

const char* mode_name(int mode) {
    switch (mode) {
        case TINYGLTF_MODE_POINTS:
            return "POINTS";
        case TINYGLTF_MODE_LINE:
            return "LINES";
        case TINYGLTF_MODE_LINE_LOOP:
            return "LINE_LOOP";
        case TINYGLTF_MODE_LINE_STRIP:
            return "LINE_STRIP";
        case TINYGLTF_MODE_TRIANGLES:
            return "TRIANGLES";
        case TINYGLTF_MODE_TRIANGLE_STRIP:
            return "TRIANGLE_STRIP";
        case TINYGLTF_MODE_TRIANGLE_FAN:
            return "TRIANGLE_FAN";
        default:
            return nullptr;
    }
}

int find_attribute(const tinygltf::Primitive& primitive, const char* name) {
    const auto it = primitive.attributes.find(name);
    return it == primitive.attributes.end() ? -1 : it->second;
}

// Attributes we ignore (COLOR_0, JOINTS_0, morph targets ...) must still name real accessors.
void check_attribute_indices(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                             const std::string& what) {
    auto check = [&](const std::string& name, int index) {
        if (index < 0 || static_cast<size_t>(index) >= model.accessors.size())
            fail(what + " " + name + ": accessor " + std::to_string(index) + " out of range");
    };
    for (const auto& [name, index] : primitive.attributes) check(name, index);
    for (const auto& target : primitive.targets)
        for (const auto& [name, index] : target) check("morph target " + name, index);
}

struct Attributes {
    size_t count = 0;
    std::vector<float> positions;  // count × 3
    std::vector<float> normals;    // count × 3 or empty
    std::vector<float> uvs;        // count × 2 or empty
    std::vector<float> tangents;   // count × 4 or empty
};

Attributes read_attributes(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                           const std::string& what) {
    check_attribute_indices(model, primitive, what);
    const int position = find_attribute(primitive, "POSITION");
    if (position < 0) fail(what + ": no POSITION attribute");
    Attributes a;
    // KHR_mesh_quantization widens the component types each attribute may have.
    const bool quantized = std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(),
                                     "KHR_mesh_quantization") != model.extensionsUsed.end();
    const Components any = quantized ? Components::AnyInteger : Components::Float;
    const Components direction = quantized ? Components::Snorm : Components::Float;
    const Components uv = quantized ? Components::AnyInteger : Components::FloatOrUnorm;
    a.positions = read_floats(model, position, {3, any}, what + " POSITION");
    a.count = a.positions.size() / 3;
    auto optional = [&](const char* name, FloatRead spec, std::vector<float>& out) {
        const int index = find_attribute(primitive, name);
        if (index < 0) return;
        out = read_floats(model, index, spec, what + " " + name);
        const size_t count = out.size() / static_cast<size_t>(spec.components);
        if (count != a.count)
            fail(what + " " + name + " has " + std::to_string(count) +
                 " elements but POSITION has " + std::to_string(a.count));
    };
    optional("NORMAL", {3, direction}, a.normals);
    optional("TEXCOORD_0", {2, uv}, a.uvs);
    optional("TANGENT", {4, direction}, a.tangents);
    return a;
}

std::vector<uint32_t> read_triangle_indices(const tinygltf::Model& model,
                                            const tinygltf::Primitive& primitive,
                                            size_t vertex_count, const std::string& what) {
    std::vector<uint32_t> indices;
    if (primitive.indices >= 0) {
        indices = read_indices(model, primitive.indices, what + " indices");
        for (uint32_t index : indices)
            if (index >= vertex_count)
                fail(what + ": index " + std::to_string(index) + " out of range (" +
                     std::to_string(vertex_count) + " vertices)");
    } else {
        indices.resize(vertex_count);
        for (size_t i = 0; i < vertex_count; ++i) indices[i] = static_cast<uint32_t>(i);
    }
    if (indices.size() % 3 != 0)
        fail(what + ": " + std::to_string(indices.size()) +
             (primitive.indices >= 0 ? " indices" : " vertices") +
             " is not a multiple of 3 (TRIANGLES)");
    return indices;
}

std::vector<Vertex> interleave(const Attributes& a) {
    std::vector<Vertex> vertices(a.count);
    for (size_t i = 0; i < a.count; ++i) {
        Vertex& v = vertices[i];
        v.position = {a.positions[i * 3], a.positions[i * 3 + 1], a.positions[i * 3 + 2]};
        if (!a.normals.empty())
            v.normal = {a.normals[i * 3], a.normals[i * 3 + 1], a.normals[i * 3 + 2]};
        if (!a.uvs.empty()) v.uv0 = {a.uvs[i * 2], a.uvs[i * 2 + 1]};
        if (!a.tangents.empty())
            v.tangent = {a.tangents[i * 4], a.tangents[i * 4 + 1], a.tangents[i * 4 + 2],
                         a.tangents[i * 4 + 3]};
    }
    return vertices;
}

Mesh import_primitive(const tinygltf::Model& model, size_t mesh_index, size_t primitive_index,
                      uint32_t default_material, bool& used_default) {
    const tinygltf::Mesh& source = model.meshes[mesh_index];
    const tinygltf::Primitive& primitive = source.primitives[primitive_index];
    const std::string what =
        "mesh " + std::to_string(mesh_index) + " primitive " + std::to_string(primitive_index);

    Mesh mesh;
    mesh.name = source.name.empty() ? "mesh " + std::to_string(mesh_index) : source.name;
    if (source.primitives.size() > 1) mesh.name += "/" + std::to_string(primitive_index);
    mesh.gltf_mesh = static_cast<uint32_t>(mesh_index);
    if (primitive.material < 0) {
        mesh.material = default_material;
        used_default = true;
    } else if (static_cast<size_t>(primitive.material) >= model.materials.size()) {
        fail(what + ": material " + std::to_string(primitive.material) + " out of range");
    } else {
        mesh.material = static_cast<uint32_t>(primitive.material);
    }

    const Attributes attributes = read_attributes(model, primitive, what);
    mesh.indices = read_triangle_indices(model, primitive, attributes.count, what);
    mesh.vertices = interleave(attributes);
    if (attributes.normals.empty()) unweld_flat_normals(mesh.vertices, mesh.indices);
    if (attributes.tangents.empty()) generate_tangents(mesh.vertices, mesh.indices);
    mesh.bounds = compute_bounds(mesh.vertices);
    return mesh;
}

}  // namespace

MeshImport import_meshes(const tinygltf::Model& model, uint32_t default_material,
                         std::vector<Mesh>& meshes) {
    MeshImport result;
    result.by_gltf_mesh.resize(model.meshes.size());
    for (size_t m = 0; m < model.meshes.size(); ++m) {
        const auto& primitives = model.meshes[m].primitives;
        if (primitives.empty()) fail("mesh " + std::to_string(m) + " has no primitives");
        for (size_t p = 0; p < primitives.size(); ++p) {
            // tinygltf leaves mode at -1 in models built in memory: the glTF default applies.
            const int mode =
                primitives[p].mode == -1 ? TINYGLTF_MODE_TRIANGLES : primitives[p].mode;
            const char* name = mode_name(mode);
            if (name == nullptr)
                fail("mesh " + std::to_string(m) + " primitive " + std::to_string(p) +
                     ": invalid mode " + std::to_string(mode));
            if (mode != TINYGLTF_MODE_TRIANGLES) {
                ++result.skipped_modes[name];
                continue;
            }
            result.by_gltf_mesh[m].push_back(static_cast<uint32_t>(meshes.size()));
            meshes.push_back(
                import_primitive(model, m, p, default_material, result.uses_default_material));
        }
    }
    return result;
}

}  // namespace ds::scene::detail
