#include "renderer/scene/mesh_ops.h"

#include <cmath>

namespace ds::scene::detail {
namespace {

// Below this, a cross product or UV determinant is treated as degenerate: the triangle gives
// no usable direction (zero area or collapsed UVs).
constexpr float kEpsilon = 1e-12f;

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Any unit vector perpendicular to `n` (or +X when `n` is unusable).
glm::vec3 any_perpendicular(const glm::vec3& n) {
    const float len2 = glm::dot(n, n);
    if (!(len2 > kEpsilon) || !std::isfinite(len2)) return {1.0f, 0.0f, 0.0f};
    const glm::vec3 unit = n / std::sqrt(len2);
    // Cross with the axis least aligned with n for the best-conditioned result.
    const glm::vec3 axis = std::abs(unit.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    return glm::normalize(glm::cross(unit, axis));
}

}  // namespace

void unweld_flat_normals(std::vector<Vertex>& vertices, std::vector<uint32_t>& indices) {
    std::vector<Vertex> out;
    out.reserve(indices.size());
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        Vertex v[3] = {vertices[indices[t]], vertices[indices[t + 1]], vertices[indices[t + 2]]};
        const glm::vec3 n =
            glm::cross(v[1].position - v[0].position, v[2].position - v[0].position);
        const float len2 = glm::dot(n, n);
        // Degenerate triangles cover no pixels; any unit normal keeps the shaders NaN-free.
        const glm::vec3 face = len2 > kEpsilon * kEpsilon && std::isfinite(len2)
                                   ? n / std::sqrt(len2)
                                   : glm::vec3(0.0f, 0.0f, 1.0f);
        for (Vertex& vertex : v) {
            vertex.normal = face;
            out.push_back(vertex);
        }
    }
    vertices = std::move(out);
    indices.resize(vertices.size());
    for (size_t i = 0; i < indices.size(); ++i) indices[i] = static_cast<uint32_t>(i);
}

void generate_tangents(std::vector<Vertex>& vertices, const std::vector<uint32_t>& indices) {
    std::vector<glm::vec3> tan_u(vertices.size(), glm::vec3(0.0f));
    std::vector<glm::vec3> tan_v(vertices.size(), glm::vec3(0.0f));
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        const uint32_t i[3] = {indices[t], indices[t + 1], indices[t + 2]};
        const glm::vec3 e1 = vertices[i[1]].position - vertices[i[0]].position;
        const glm::vec3 e2 = vertices[i[2]].position - vertices[i[0]].position;
        const glm::vec2 d1 = vertices[i[1]].uv0 - vertices[i[0]].uv0;
        const glm::vec2 d2 = vertices[i[2]].uv0 - vertices[i[0]].uv0;
        const float det = d1.x * d2.y - d2.x * d1.y;
        if (!(std::abs(det) > kEpsilon) || !std::isfinite(det)) continue;  // no UV gradient
        const float r = 1.0f / det;
        const glm::vec3 sdir = (e1 * d2.y - e2 * d1.y) * r;
        const glm::vec3 tdir = (e2 * d1.x - e1 * d2.x) * r;
        if (!finite(sdir) || !finite(tdir)) continue;
        for (uint32_t k : i) {
            tan_u[k] += sdir;
            tan_v[k] += tdir;
        }
    }
    for (size_t k = 0; k < vertices.size(); ++k) {
        const glm::vec3 n = vertices[k].normal;
        glm::vec3 t = tan_u[k] - n * glm::dot(n, tan_u[k]);
        const float len2 = glm::dot(t, t);
        if (len2 > kEpsilon && std::isfinite(len2)) {
            t /= std::sqrt(len2);
        } else {
            t = any_perpendicular(n);
        }
        // glTF's bitangent cross(n, t) * w is tangent-space +Y, "up" in the normal map, i.e.
        // towards decreasing v (UV origin top-left); tan_v points towards increasing v.
        const float w = glm::dot(glm::cross(n, t), tan_v[k]) > 0.0f ? -1.0f : 1.0f;
        vertices[k].tangent = glm::vec4(t, w);
    }
}

Bounds compute_bounds(const std::vector<Vertex>& vertices) {
    Bounds b;
    for (const Vertex& v : vertices) b.extend(v.position);
    return b;
}

Bounds transform_bounds(const Bounds& local, const glm::mat4& world) {
    Bounds out;
    if (!local.valid()) return out;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p{(corner & 1) ? local.max.x : local.min.x,
                          (corner & 2) ? local.max.y : local.min.y,
                          (corner & 4) ? local.max.z : local.min.z};
        const glm::vec4 w = world * glm::vec4(p, 1.0f);
        out.extend(glm::vec3(w));
    }
    return out;
}

}  // namespace ds::scene::detail
