#include "model_view.h"

#include <cmath>
#include <cstring>
#include <functional>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace ds::test {

namespace {

const unsigned char* element(const tinygltf::Model& m, const tinygltf::Accessor& a, size_t i,
                             size_t element_size) {
    const tinygltf::BufferView& v = m.bufferViews.at(static_cast<size_t>(a.bufferView));
    const size_t stride = v.byteStride ? v.byteStride : element_size;
    const size_t offset = v.byteOffset + a.byteOffset + i * stride;
    const tinygltf::Buffer& b = m.buffers.at(static_cast<size_t>(v.buffer));
    if (offset + element_size > b.data.size() ||
        a.byteOffset + i * stride + element_size > v.byteLength) {
        throw std::out_of_range("accessor element outside its bufferView");
    }
    return b.data.data() + offset;
}

}  // namespace

std::vector<glm::vec3> read_vec3(const tinygltf::Model& m, int accessor) {
    const tinygltf::Accessor& a = m.accessors.at(static_cast<size_t>(accessor));
    if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || a.type != TINYGLTF_TYPE_VEC3) {
        throw std::invalid_argument("not a float VEC3 accessor");
    }
    std::vector<glm::vec3> out(a.count);
    for (size_t i = 0; i < a.count; ++i) std::memcpy(&out[i], element(m, a, i, 12), 12);
    return out;
}

std::vector<uint32_t> read_indices(const tinygltf::Model& m, int accessor) {
    const tinygltf::Accessor& a = m.accessors.at(static_cast<size_t>(accessor));
    std::vector<uint32_t> out(a.count);
    for (size_t i = 0; i < a.count; ++i) {
        switch (a.componentType) {
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
                out[i] = *element(m, a, i, 1);
                break;
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                uint16_t v;
                std::memcpy(&v, element(m, a, i, 2), 2);
                out[i] = v;
                break;
            }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
                std::memcpy(&out[i], element(m, a, i, 4), 4);
                break;
            default:
                throw std::invalid_argument("bad index component type");
        }
    }
    return out;
}

glm::mat4 node_local_matrix(const tinygltf::Node& n) {
    if (n.matrix.size() == 16) {
        glm::mat4 m;
        for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = static_cast<float>(n.matrix[i]);
        return m;
    }
    glm::mat4 m(1.0f);
    if (n.translation.size() == 3) {
        m = glm::translate(m, glm::vec3(n.translation[0], n.translation[1], n.translation[2]));
    }
    if (n.rotation.size() == 4) {
        const glm::quat q(static_cast<float>(n.rotation[3]), static_cast<float>(n.rotation[0]),
                          static_cast<float>(n.rotation[1]), static_cast<float>(n.rotation[2]));
        m = m * glm::mat4_cast(q);
    }
    if (n.scale.size() == 3) m = glm::scale(m, glm::vec3(n.scale[0], n.scale[1], n.scale[2]));
    return m;
}

std::vector<glm::mat4> world_matrices(const tinygltf::Model& m) {
    std::vector<glm::mat4> world(m.nodes.size(), glm::mat4(1.0f));
    std::function<void(int, const glm::mat4&)> visit = [&](int node, const glm::mat4& parent) {
        const tinygltf::Node& n = m.nodes.at(static_cast<size_t>(node));
        world[static_cast<size_t>(node)] = parent * node_local_matrix(n);
        for (int child : n.children) visit(child, world[static_cast<size_t>(node)]);
    };
    const int scene = m.defaultScene >= 0 ? m.defaultScene : 0;
    if (!m.scenes.empty()) {
        for (int root : m.scenes.at(static_cast<size_t>(scene)).nodes) visit(root, glm::mat4(1));
    }
    return world;
}

std::vector<WorldTriangle> world_triangles(const tinygltf::Model& m) {
    const std::vector<glm::mat4> world = world_matrices(m);
    std::vector<WorldTriangle> out;
    for (size_t ni = 0; ni < m.nodes.size(); ++ni) {
        const int mesh = m.nodes[ni].mesh;
        if (mesh < 0) continue;
        for (const tinygltf::Primitive& prim : m.meshes.at(static_cast<size_t>(mesh)).primitives) {
            const std::vector<glm::vec3> pos = read_vec3(m, prim.attributes.at("POSITION"));
            const std::vector<uint32_t> idx = read_indices(m, prim.indices);
            const bool ds = prim.material >= 0 &&
                            m.materials.at(static_cast<size_t>(prim.material)).doubleSided;
            for (size_t t = 0; t + 2 < idx.size(); t += 3) {
                WorldTriangle tri;
                for (int k = 0; k < 3; ++k) {
                    tri.p[k] = glm::vec3(world[ni] * glm::vec4(pos.at(idx[t + k]), 1.0f));
                }
                tri.material = prim.material;
                tri.mesh = mesh;
                tri.node = static_cast<int>(ni);
                tri.double_sided = ds;
                out.push_back(tri);
            }
        }
    }
    return out;
}

std::optional<ViewCamera> find_camera(const tinygltf::Model& m) {
    const std::vector<glm::mat4> world = world_matrices(m);
    for (size_t ni = 0; ni < m.nodes.size(); ++ni) {
        const int cam = m.nodes[ni].camera;
        if (cam < 0) continue;
        const tinygltf::Camera& c = m.cameras.at(static_cast<size_t>(cam));
        if (c.type != "perspective") continue;
        ViewCamera v;
        v.view = glm::inverse(world[ni]);
        v.yfov = static_cast<float>(c.perspective.yfov);
        if (c.perspective.aspectRatio > 0.0)
            v.aspect = static_cast<float>(c.perspective.aspectRatio);
        v.znear = static_cast<float>(c.perspective.znear);
        if (c.perspective.zfar > 0.0) v.zfar = static_cast<float>(c.perspective.zfar);
        return v;
    }
    return std::nullopt;
}

ViewCamera look_at(const glm::vec3& eye, const glm::vec3& target, float yfov, float aspect) {
    ViewCamera v;
    const glm::vec3 dir = glm::normalize(target - eye);
    const glm::vec3 up = std::abs(dir.y) > 0.99f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
    v.view = glm::lookAt(eye, target, up);
    v.yfov = yfov;
    v.aspect = aspect;
    return v;
}

}  // namespace ds::test
