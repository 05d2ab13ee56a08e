#include "renderer/scene/fit_inside.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace ds::scene {
namespace {

// Whether the ray o + t d (0 <= t <= t_max) meets box `b` (slab test; an axis the ray runs
// along needs o inside the slab).
bool meets_box(const Bounds& b, const glm::vec3& o, const glm::vec3& d, float t_max) {
    float near = 0.0f, far = t_max;
    for (int axis = 0; axis < 3; ++axis) {
        if (d[axis] == 0.0f) {
            if (o[axis] < b.min[axis] || o[axis] > b.max[axis]) return false;
            continue;
        }
        float t0 = (b.min[axis] - o[axis]) / d[axis];
        float t1 = (b.max[axis] - o[axis]) / d[axis];
        if (t0 > t1) std::swap(t0, t1);
        near = std::max(near, t0);
        far = std::min(far, t1);
        if (near > far) return false;
    }
    return true;
}

// Möller-Trumbore: t of the hit, or none; `det` > 0 when the ray meets the front face.
bool hit_triangle(const glm::vec3& o, const glm::vec3& d, const glm::vec3& a, const glm::vec3& b,
                  const glm::vec3& c, float& t, float& det) {
    const glm::vec3 e1 = b - a, e2 = c - a;
    const glm::vec3 p = glm::cross(d, e2);
    det = glm::dot(e1, p);
    if (std::fabs(det) < 1e-20f) return false;  // parallel (or degenerate)
    const float inv = 1.0f / det;
    const glm::vec3 s = o - a;
    const float u = glm::dot(s, p) * inv;
    if (u < 0.0f || u > 1.0f) return false;
    const glm::vec3 q = glm::cross(s, e1);
    const float v = glm::dot(d, q) * inv;
    if (v < 0.0f || u + v > 1.0f) return false;
    t = glm::dot(e2, q) * inv;
    return true;
}

// The ray's hits on one instance, tested in the mesh's own space (an affine map keeps t).
void cast_instance(const Scene& scene, const Instance& instance, const glm::vec3& origin,
                   const glm::vec3& direction, float t_max, std::vector<RayHit>& hits) {
    const Mesh& mesh = scene.meshes[instance.mesh];
    const glm::mat4 inverse = glm::inverse(instance.world);
    const glm::vec3 o = glm::vec3(inverse * glm::vec4(origin, 1.0f));
    const glm::vec3 d = glm::vec3(inverse * glm::vec4(direction, 0.0f));
    if (!mesh.bounds.valid() || !meets_box(mesh.bounds, o, d, t_max)) return;
    // A mirroring transform turns the winding over.
    const bool mirrored = glm::determinant(glm::mat3(instance.world)) < 0.0f;
    const bool double_sided = scene.materials[mesh.material].double_sided;
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        float t = 0.0f, det = 0.0f;
        if (!hit_triangle(o, d, mesh.vertices[mesh.indices[i]].position,
                          mesh.vertices[mesh.indices[i + 1]].position,
                          mesh.vertices[mesh.indices[i + 2]].position, t, det))
            continue;
        if (t > 0.0f && t <= t_max) hits.push_back({t, (det > 0.0f) != mirrored, double_sided});
    }
}

// A free stretch of the vertical line: from a floor at `bottom` up to `top`.
struct Gap {
    float bottom = 0.0f, top = 0.0f;
};

// The tallest open gap on the vertical line through (x, z) within the bounds, or none.
std::optional<Gap> tallest_gap(const Scene& scene, float x, float z) {
    const Bounds& b = scene.bounds;
    const float margin = 1e-3f * std::max(glm::length(b.extent()), 1e-3f);
    const glm::vec3 top(x, b.max.y + margin, z);
    std::vector<RayHit> hits =
        cast_ray(scene, top, glm::vec3(0, -1, 0), b.max.y - b.min.y + 2.0f * margin);
    std::sort(hits.begin(), hits.end(),
              [](const RayHit& l, const RayHit& r) { return l.t > r.t; });  // bottom first
    std::optional<Gap> best;
    for (size_t i = 0; i < hits.size(); ++i) {
        // Going down, a front face faces up: a floor. Above it the next hit must face down.
        const RayHit& floor = hits[i];
        if (!floor.front && !floor.double_sided) continue;
        const RayHit* ceiling = i + 1 < hits.size() ? &hits[i + 1] : nullptr;
        if (ceiling && ceiling->front && !ceiling->double_sided) continue;
        const Gap gap{top.y - floor.t, ceiling ? top.y - ceiling->t : b.max.y};
        if (gap.top - gap.bottom > margin &&
            (!best || gap.top - gap.bottom > best->top - best->bottom))
            best = gap;
    }
    return best;
}

// How far the ray runs inside the bounds before it meets a triangle.
float free_distance(const Scene& scene, const glm::vec3& eye, const glm::vec3& direction) {
    const Bounds& b = scene.bounds;
    float reach = 0.0f;  // to the bounds' side along an axis direction
    for (int axis = 0; axis < 3; ++axis) {
        if (direction[axis] > 0.0f) reach = (b.max[axis] - eye[axis]) / direction[axis];
        if (direction[axis] < 0.0f) reach = (b.min[axis] - eye[axis]) / direction[axis];
    }
    float nearest = std::max(reach, 0.0f);
    for (const RayHit& hit : cast_ray(scene, eye, direction, nearest))
        nearest = std::min(nearest, hit.t);
    return nearest;
}

}  // namespace

std::vector<RayHit> cast_ray(const Scene& scene, const glm::vec3& origin,
                             const glm::vec3& direction, float t_max) {
    std::vector<RayHit> hits;
    for (const Instance& instance : scene.instances)
        cast_instance(scene, instance, origin, direction, t_max, hits);
    return hits;
}

Camera fit_inside(const Scene& scene, const Camera& like) {
    Camera c = like;
    const Bounds& b = scene.bounds;
    if (!b.valid()) return c;
    glm::vec3 eye = b.center();
    if (const std::optional<Gap> gap = tallest_gap(scene, eye.x, eye.z))
        eye.y = gap->bottom + std::min(kEyeHeight, 0.5f * (gap->top - gap->bottom));
    const glm::vec3 extent = b.extent();
    const glm::vec3 axis = extent.x >= extent.z ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
    const bool positive = free_distance(scene, eye, axis) > free_distance(scene, eye, -axis);
    c.position = eye;
    c.forward = positive ? axis : -axis;
    c.up = glm::vec3(0, 1, 0);
    const float reach = glm::length(b.center() - eye) + 0.5f * glm::length(extent);
    c.zfar = std::max(c.zfar, 1.05f * reach);
    return c;
}

}  // namespace ds::scene
