#include "renderer/scene/builtin/shapes.h"
#include "renderer/scene/builtin/angles.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace ds::scene::builtin {

namespace {

// One box face: origin corner, two edge vectors (u right, v up as seen from the front).
void add_face(MeshData& mesh, const glm::vec3& corner, const glm::vec3& edge_u,
              const glm::vec3& edge_v, float uv_per_meter) {
    const glm::vec3 n = glm::normalize(glm::cross(edge_u, edge_v));
    const glm::vec2 uv_max = uv_per_meter > 0.0f ? glm::vec2(glm::length(edge_u) * uv_per_meter,
                                                             glm::length(edge_v) * uv_per_meter)
                                                 : glm::vec2(1.0f);
    const uint32_t a = mesh.add_vertex(corner, n, {0.0f, uv_max.y});
    const uint32_t b = mesh.add_vertex(corner + edge_u, n, {uv_max.x, uv_max.y});
    const uint32_t c = mesh.add_vertex(corner + edge_u + edge_v, n, {uv_max.x, 0.0f});
    const uint32_t d = mesh.add_vertex(corner + edge_v, n, {0.0f, 0.0f});
    mesh.add_quad(a, b, c, d);
}

// Point where the ray from the origin at angle `theta` leaves the rectangle [-hw,hw] x [0,h].
glm::vec2 rect_boundary(float theta, float hw, float h) {
    const float c = std::cos(theta);
    const float s = std::sin(theta);
    float t = 1e30f;
    if (std::abs(c) > 1e-6f) t = hw / std::abs(c);
    if (s > 1e-6f) t = std::min(t, h / s);
    return {c * t, s * t};
}

// Front face of the arch at z; `facing` +1 faces +Z, -1 faces -Z.
void add_arch_face(MeshData& mesh, const std::vector<float>& angles, float hw, float h,
                   float radius, float z, float facing) {
    const glm::vec3 n(0.0f, 0.0f, facing);
    const float uv_scale = 0.5f;  // one texture repeat per 2 m
    std::vector<uint32_t> inner, outer;
    for (float theta : angles) {
        const glm::vec2 a(radius * std::cos(theta), radius * std::sin(theta));
        const glm::vec2 b = rect_boundary(theta, hw, h);
        const float sx = facing;  // mirror u on the back face so the texture is not reversed
        inner.push_back(mesh.add_vertex({a, z}, n, {sx * a.x * uv_scale, -a.y * uv_scale}));
        outer.push_back(mesh.add_vertex({b, z}, n, {sx * b.x * uv_scale, -b.y * uv_scale}));
    }
    for (size_t i = 0; i + 1 < angles.size(); ++i) {
        // Angles decrease from pi to 0, i.e. the strip runs left to right.
        if (facing > 0.0f) {
            mesh.add_quad(inner[i], inner[i + 1], outer[i + 1], outer[i]);
        } else {
            mesh.add_quad(inner[i], outer[i], outer[i + 1], inner[i + 1]);
        }
    }
}

}  // namespace

uint32_t MeshData::add_vertex(const glm::vec3& p, const glm::vec3& n, const glm::vec2& uv) {
    positions.push_back(p);
    normals.push_back(n);
    uvs.push_back(uv);
    return vertex_count() - 1;
}

void MeshData::add_quad(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    indices.insert(indices.end(), {a, b, c, a, c, d});
}

void MeshData::append(const MeshData& other, const glm::mat4& m) {
    const uint32_t base = vertex_count();
    const glm::mat3 nm = glm::inverseTranspose(glm::mat3(m));
    for (size_t i = 0; i < other.positions.size(); ++i) {
        positions.push_back(glm::vec3(m * glm::vec4(other.positions[i], 1.0f)));
        normals.push_back(glm::normalize(nm * other.normals[i]));
        uvs.push_back(other.uvs[i]);
    }
    for (uint32_t idx : other.indices) indices.push_back(base + idx);
}

std::vector<glm::vec4> compute_tangents(const MeshData& mesh) {
    std::vector<glm::vec3> tan(mesh.positions.size(), glm::vec3(0.0f));
    std::vector<glm::vec3> bitan(mesh.positions.size(), glm::vec3(0.0f));
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
        const glm::vec3 e1 = mesh.positions[i1] - mesh.positions[i0];
        const glm::vec3 e2 = mesh.positions[i2] - mesh.positions[i0];
        const glm::vec2 d1 = mesh.uvs[i1] - mesh.uvs[i0];
        const glm::vec2 d2 = mesh.uvs[i2] - mesh.uvs[i0];
        const float det = d1.x * d2.y - d2.x * d1.y;
        if (std::abs(det) < 1e-12f) continue;
        const float r = 1.0f / det;
        const glm::vec3 t_dir = (e1 * d2.y - e2 * d1.y) * r;
        const glm::vec3 b_dir = (e2 * d1.x - e1 * d2.x) * r;
        for (uint32_t i : {i0, i1, i2}) {
            tan[i] += t_dir;
            bitan[i] += b_dir;
        }
    }
    std::vector<glm::vec4> out(mesh.positions.size());
    for (size_t i = 0; i < out.size(); ++i) {
        const glm::vec3 n = mesh.normals[i];
        glm::vec3 t = tan[i] - n * glm::dot(n, tan[i]);  // Gram-Schmidt
        if (glm::dot(t, t) < 1e-12f) {
            // Degenerate UVs: any unit vector perpendicular to n keeps the shader NaN-free.
            t = std::abs(n.x) < 0.9f ? glm::cross(n, glm::vec3(1, 0, 0))
                                     : glm::cross(n, glm::vec3(0, 1, 0));
        }
        t = glm::normalize(t);
        // glTF: the bitangent cross(n, t) * w is tangent-space +Y, "up" in the normal map, i.e.
        // towards decreasing v; bitan points towards increasing v (as in the importer).
        const float w = glm::dot(glm::cross(n, t), bitan[i]) > 0.0f ? -1.0f : 1.0f;
        out[i] = glm::vec4(t, w);
    }
    return out;
}

MeshData make_quad(glm::vec2 size, glm::vec2 uv_scale) {
    MeshData mesh;
    const glm::vec2 h = size * 0.5f;
    const glm::vec3 n(0.0f, 0.0f, 1.0f);
    const uint32_t a = mesh.add_vertex({-h.x, -h.y, 0.0f}, n, {0.0f, uv_scale.y});
    const uint32_t b = mesh.add_vertex({h.x, -h.y, 0.0f}, n, {uv_scale.x, uv_scale.y});
    const uint32_t c = mesh.add_vertex({h.x, h.y, 0.0f}, n, {uv_scale.x, 0.0f});
    const uint32_t d = mesh.add_vertex({-h.x, h.y, 0.0f}, n, {0.0f, 0.0f});
    mesh.add_quad(a, b, c, d);
    return mesh;
}

MeshData make_box(const glm::vec3& lo, const glm::vec3& hi, float uv_per_meter,
                  uint32_t skip_faces) {
    MeshData mesh;
    const glm::vec3 d = hi - lo;
    const glm::vec3 ex(d.x, 0, 0), ey(0, d.y, 0), ez(0, 0, d.z);
    if (!(skip_faces & kFacePosZ)) add_face(mesh, {lo.x, lo.y, hi.z}, ex, ey, uv_per_meter);
    if (!(skip_faces & kFaceNegZ)) add_face(mesh, {hi.x, lo.y, lo.z}, -ex, ey, uv_per_meter);
    if (!(skip_faces & kFacePosX)) add_face(mesh, {hi.x, lo.y, hi.z}, -ez, ey, uv_per_meter);
    if (!(skip_faces & kFaceNegX)) add_face(mesh, {lo.x, lo.y, lo.z}, ez, ey, uv_per_meter);
    if (!(skip_faces & kFacePosY)) add_face(mesh, {lo.x, hi.y, hi.z}, ex, -ez, uv_per_meter);
    if (!(skip_faces & kFaceNegY)) add_face(mesh, {lo.x, lo.y, lo.z}, ex, ez, uv_per_meter);
    return mesh;
}

MeshData make_frustum(float r_bottom, float r_top, float height, int segments, float uv_v) {
    MeshData mesh;
    const float slope = (r_bottom - r_top) / height;  // normal tilts up when the top is narrower
    for (int i = 0; i <= segments; ++i) {
        const float a = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(segments);
        const glm::vec3 dir(std::cos(a), 0.0f, -std::sin(a));
        const glm::vec3 n = glm::normalize(glm::vec3(dir.x, slope, dir.z));
        const float u = static_cast<float>(i) / static_cast<float>(segments);
        mesh.add_vertex(dir * r_bottom, n, {u, uv_v});
        mesh.add_vertex(dir * r_top + glm::vec3(0, height, 0), n, {u, 0.0f});
    }
    for (uint32_t i = 0; i < static_cast<uint32_t>(segments); ++i) {
        mesh.add_quad(2 * i, 2 * i + 2, 2 * i + 3, 2 * i + 1);
    }
    for (int cap = 0; cap < 2; ++cap) {  // 0: bottom (faces -Y), 1: top (faces +Y)
        const float y = cap ? height : 0.0f;
        const float r = cap ? r_top : r_bottom;
        const glm::vec3 n(0.0f, cap ? 1.0f : -1.0f, 0.0f);
        const uint32_t centre = mesh.add_vertex({0, y, 0}, n, {0.5f, 0.5f});
        for (int i = 0; i <= segments; ++i) {
            const float a = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(segments);
            mesh.add_vertex({r * std::cos(a), y, -r * std::sin(a)}, n,
                            {0.5f + 0.5f * std::cos(a), 0.5f - 0.5f * std::sin(a)});
        }
        for (uint32_t i = 0; i < static_cast<uint32_t>(segments); ++i) {
            const uint32_t a = centre + 1 + i, b = centre + 2 + i;
            if (cap) {
                mesh.indices.insert(mesh.indices.end(), {centre, a, b});
            } else {
                mesh.indices.insert(mesh.indices.end(), {centre, b, a});
            }
        }
    }
    return mesh;
}

MeshData make_grid(const glm::vec3& origin, const glm::vec3& axis_u, const glm::vec3& axis_v,
                   glm::vec2 cell, GridRange r, float uv_per_meter) {
    MeshData mesh;
    const glm::vec3 n = glm::normalize(glm::cross(axis_u, axis_v));
    const int nu = r.i1 - r.i0, nv = r.j1 - r.j0;
    for (int j = r.j0; j <= r.j1; ++j) {
        for (int i = r.i0; i <= r.i1; ++i) {
            const float du = static_cast<float>(i) * cell.x;
            const float dv = static_cast<float>(j) * cell.y;
            const glm::vec3 p = origin + axis_u * du + axis_v * dv;
            const glm::vec2 uv =
                uv_per_meter > 0.0f
                    ? glm::vec2(du, -dv) * uv_per_meter
                    : glm::vec2(static_cast<float>(i - r.i0) / static_cast<float>(nu),
                                1.0f - static_cast<float>(j - r.j0) / static_cast<float>(nv));
            mesh.add_vertex(p, n, uv);
        }
    }
    const uint32_t row = static_cast<uint32_t>(nu + 1);
    for (uint32_t j = 0; j < static_cast<uint32_t>(nv); ++j) {
        for (uint32_t i = 0; i < static_cast<uint32_t>(nu); ++i) {
            const uint32_t a = j * row + i;
            mesh.add_quad(a, a + 1, a + row + 1, a + row);
        }
    }
    return mesh;
}

MeshData make_arch(float span, float height, float depth, float radius, int segments) {
    const float hw = span * 0.5f, hd = depth * 0.5f;
    // Angles from pi down to 0, plus the two top corners so the outline is exact.
    std::vector<float> angles;
    for (int i = 0; i <= segments; ++i) {
        angles.push_back(kPi * (1.0f - static_cast<float>(i) / static_cast<float>(segments)));
    }
    const float corner = std::atan2(height, hw);
    angles.push_back(corner);
    angles.push_back(kPi - corner);
    std::sort(angles.begin(), angles.end(), std::greater<float>());
    angles.erase(std::unique(angles.begin(), angles.end(),
                             [](float a, float b) { return std::abs(a - b) < 1e-5f; }),
                 angles.end());

    MeshData mesh;
    add_arch_face(mesh, angles, hw, height, radius, hd, 1.0f);
    add_arch_face(mesh, angles, hw, height, radius, -hd, -1.0f);
    // Intrados: the curved underside, facing the centre of the opening.
    for (size_t i = 0; i + 1 < angles.size(); ++i) {
        const float a0 = angles[i], a1 = angles[i + 1];
        const glm::vec3 p0(radius * std::cos(a0), radius * std::sin(a0), 0.0f);
        const glm::vec3 p1(radius * std::cos(a1), radius * std::sin(a1), 0.0f);
        const glm::vec3 n0 = -glm::normalize(p0), n1 = -glm::normalize(p1);
        const float u0 = a0 * radius * 0.5f, u1 = a1 * radius * 0.5f;
        const uint32_t v0 = mesh.add_vertex(p0 + glm::vec3(0, 0, hd), n0, {u0, 0.0f});
        const uint32_t v1 = mesh.add_vertex(p1 + glm::vec3(0, 0, hd), n1, {u1, 0.0f});
        const uint32_t v2 = mesh.add_vertex(p1 - glm::vec3(0, 0, hd), n1, {u1, depth * 0.5f});
        const uint32_t v3 = mesh.add_vertex(p0 - glm::vec3(0, 0, hd), n0, {u0, depth * 0.5f});
        mesh.add_quad(v0, v3, v2, v1);
    }
    // Top, the two pier ends and the pier bottoms beside the opening.
    mesh.append(
        make_box({-hw, 0.0f, -hd}, {hw, height, hd}, 0.5f, kFaceNegZ | kFacePosZ | kFaceNegY));
    mesh.append(make_box({-hw, 0.0f, -hd}, {-radius, 0.0f, hd}, 0.5f, ~kFaceNegY));
    mesh.append(make_box({radius, 0.0f, -hd}, {hw, 0.0f, hd}, 0.5f, ~kFaceNegY));
    return mesh;
}

MeshData make_curtain(float width, float height, int folds, float amp) {
    MeshData mesh;
    const int nx = folds * 8, ny = 6;
    const float k = 2.0f * kPi * static_cast<float>(folds) / width;
    for (int j = 0; j <= ny; ++j) {
        const float t = static_cast<float>(j) / static_cast<float>(ny);
        const float a = amp * (0.6f + 0.6f * t);  // folds open up towards the hem
        for (int i = 0; i <= nx; ++i) {
            const float x = width * (static_cast<float>(i) / static_cast<float>(nx) - 0.5f);
            const glm::vec3 p(x, -height * t, a * std::sin(k * x));
            const glm::vec3 n = glm::normalize(glm::vec3(-a * k * std::cos(k * x), 0.0f, 1.0f));
            mesh.add_vertex(p, n,
                            {static_cast<float>(i) / static_cast<float>(nx) * 2.0f, t * 3.0f});
        }
    }
    const uint32_t row = static_cast<uint32_t>(nx + 1);
    for (uint32_t j = 0; j < static_cast<uint32_t>(ny); ++j) {
        for (uint32_t i = 0; i < static_cast<uint32_t>(nx); ++i) {
            const uint32_t top = j * row + i, bottom = top + row;
            mesh.add_quad(bottom, bottom + 1, top + 1, top);
        }
    }
    return mesh;
}

MeshData make_plant_cards(float radius, float height, int cards, int tilted) {
    MeshData mesh;
    const MeshData card = make_quad({2.0f * radius, height});
    for (int i = 0; i < cards; ++i) {
        const float a = kPi * static_cast<float>(i) / static_cast<float>(cards);
        glm::mat4 m = glm::translate(glm::mat4(1.0f), {0.0f, height * 0.5f, 0.0f});
        mesh.append(card, glm::rotate(m, a, glm::vec3(0, 1, 0)));
    }
    for (int i = 0; i < tilted; ++i) {
        const float a = 2.0f * kPi * (static_cast<float>(i) + 0.5f) / static_cast<float>(tilted);
        glm::mat4 m = glm::rotate(glm::mat4(1.0f), a, glm::vec3(0, 1, 0));
        m = glm::translate(m, {0.0f, 0.1f * height, radius * 0.5f});
        m = glm::rotate(m, 0.6f, glm::vec3(1, 0, 0));  // lean outwards
        m = glm::translate(m, {0.0f, height * 0.4f, 0.0f});
        mesh.append(make_quad({radius * 1.2f, height * 0.8f}), m);
    }
    return mesh;
}

}  // namespace ds::scene::builtin
