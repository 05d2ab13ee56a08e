#pragma once
// Builds small tinygltf models in memory for importer tests (the same path built-in scenes
// take). All data goes into buffer 0; every accessor gets its own buffer view.
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <tiny_gltf.h>
#include <glm/glm.hpp>

#include "renderer/common/error.h"
#include "renderer/scene/importer.h"

namespace ds::scene::test {

class ModelBuilder {
  public:
    tinygltf::Model model;

    ModelBuilder() {
        model.asset.version = "2.0";
        model.buffers.emplace_back();
        model.scenes.emplace_back();
        model.defaultScene = 0;
    }

    // Raw bytes as a new buffer view + accessor of `count` elements.
    int add_accessor(const void* bytes, size_t size, size_t count, int component_type, int type,
                     bool normalized = false) {
        std::vector<unsigned char>& data = model.buffers[0].data;
        while (data.size() % 4 != 0) data.push_back(0);
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = data.size();
        view.byteLength = size;
        data.resize(data.size() + size);
        std::memcpy(data.data() + view.byteOffset, bytes, size);
        model.bufferViews.push_back(view);
        tinygltf::Accessor accessor;
        accessor.bufferView = static_cast<int>(model.bufferViews.size() - 1);
        accessor.componentType = component_type;
        accessor.type = type;
        accessor.count = count;
        accessor.normalized = normalized;
        model.accessors.push_back(accessor);
        return static_cast<int>(model.accessors.size() - 1);
    }

    int add_vec3(const std::vector<glm::vec3>& v) {
        return add_accessor(v.data(), v.size() * sizeof(glm::vec3), v.size(),
                            TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3);
    }
    int add_vec2(const std::vector<glm::vec2>& v) {
        return add_accessor(v.data(), v.size() * sizeof(glm::vec2), v.size(),
                            TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2);
    }
    template <typename T>
    int add_indices(const std::vector<T>& v, int component_type) {
        return add_accessor(v.data(), v.size() * sizeof(T), v.size(), component_type,
                            TINYGLTF_TYPE_SCALAR);
    }

    // A unit quad in the XY plane facing +Z (4 vertices, 2 triangles, u16 indices).
    int add_quad_mesh(int material = -1, bool with_normals = true) {
        const int positions = add_vec3({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
        const int indices =
            add_indices<uint16_t>({0, 1, 2, 0, 2, 3}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
        tinygltf::Primitive p;
        p.attributes["POSITION"] = positions;
        if (with_normals)
            p.attributes["NORMAL"] = add_vec3({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
        p.attributes["TEXCOORD_0"] = add_vec2({{0, 1}, {1, 1}, {1, 0}, {0, 0}});
        p.indices = indices;
        p.material = material;
        p.mode = TINYGLTF_MODE_TRIANGLES;
        return add_mesh({p});
    }

    int add_mesh(std::vector<tinygltf::Primitive> primitives, std::string name = {}) {
        tinygltf::Mesh mesh;
        mesh.name = std::move(name);
        mesh.primitives = std::move(primitives);
        model.meshes.push_back(mesh);
        return static_cast<int>(model.meshes.size() - 1);
    }

    int add_material(const std::string& alpha_mode = "OPAQUE", bool double_sided = false) {
        tinygltf::Material m;
        m.alphaMode = alpha_mode;
        m.doubleSided = double_sided;
        model.materials.push_back(m);
        return static_cast<int>(model.materials.size() - 1);
    }

    // A node with `mesh` (or -1), translated by `t`; it becomes a scene root unless `root` is
    // false.
    int add_node(int mesh, glm::vec3 t = glm::vec3(0.0f), bool root = true) {
        tinygltf::Node node;
        node.mesh = mesh;
        if (t != glm::vec3(0.0f)) node.translation = {t.x, t.y, t.z};
        model.nodes.push_back(node);
        const int index = static_cast<int>(model.nodes.size() - 1);
        if (root) model.scenes[0].nodes.push_back(index);
        return index;
    }

    // An RGBA8 image of w×h pixels with the given components and bits, already "decoded".
    int add_image(int w, int h, int components, int bits, std::vector<unsigned char> pixels) {
        tinygltf::Image image;
        image.width = w;
        image.height = h;
        image.component = components;
        image.bits = bits;
        image.pixel_type = bits == 16 ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT
                                      : TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
        image.image = std::move(pixels);
        model.images.push_back(image);
        return static_cast<int>(model.images.size() - 1);
    }

    int add_texture(int image, int sampler = -1) {
        tinygltf::Texture t;
        t.source = image;
        t.sampler = sampler;
        model.textures.push_back(t);
        return static_cast<int>(model.textures.size() - 1);
    }
};

// The InputError message of importing `model` ("" when it imports).
inline std::string import_error(const tinygltf::Model& model) {
    try {
        ds::scene::import_model(model, "t", "mem:t");
    } catch (const ds::InputError& e) {
        return e.what();
    }
    return "";
}

#define EXPECT_IMPORT_ERROR(model, what)                                    \
    do {                                                                    \
        const std::string message = ::ds::scene::test::import_error(model); \
        EXPECT_EQ(message.rfind("mem:t: ", 0), 0u) << message;              \
        EXPECT_NE(message.find(what), std::string::npos) << message;        \
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;        \
    } while (0)

}  // namespace ds::scene::test
