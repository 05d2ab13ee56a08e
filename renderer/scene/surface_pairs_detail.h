#pragma once
// The parts of find_surface_pairs (surface_pairs.h): the triangle-pair test
// (surface_pairs_clip.cpp) and the in-plane broadphase (surface_pairs_grid.cpp).
#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/scene/scene.h"

namespace ds::scene::detail {

// An instance as the pair search sees it.
struct PairInstance {
    const Mesh* mesh = nullptr;  // null: the instance names no mesh
    glm::dmat4 world{1.0};
    double facing = 1.0;  // -1 when the transform mirrors (negative determinant)
    bool double_sided = false;
};

struct WorldTriangle {
    std::array<glm::dvec3, 3> p;
    glm::dvec3 n{0.0};  // unit facing normal (surface_pairs.h)
    double longest = 0.0;
};

// Vertex `vertex` (in range) of the instance's mesh in world space.
inline glm::dvec3 world_position(const PairInstance& instance, uint32_t vertex) {
    const glm::dvec3 local(instance.mesh->vertices[vertex].position);
    return glm::dvec3(instance.world * glm::dvec4(local, 1.0));
}

// Triangle `triangle` (index / 3) of `instance` in world space; false when it is out of range
// or degenerate.
bool world_triangle(const PairInstance& instance, uint32_t triangle, WorldTriangle& out);

enum class Contact : uint8_t { None, Coplanar, Near };
struct TriangleContact {
    Contact kind = Contact::None;
    double area = 0.0;
    double min_gap = 0.0, max_gap = 0.0;  // |gap| over the overlap's vertices
    glm::dvec3 point{0.0};                // inside the overlap, on a's plane
};

// The rules of surface_pairs.h for triangle `a` of the lower instance and `b` of the higher.
TriangleContact triangle_contact(const WorldTriangle& a, const WorldTriangle& b,
                                 bool either_double_sided, double near_gap_max);

// A triangle's box in a direction bin's frame (x, y in the plane, z along the normal), grown
// by its share of the gap it may pair across.
struct PlaneEntry {
    glm::dvec3 lo{0.0}, hi{0.0};
    uint32_t instance = 0;
    uint32_t triangle = 0;
};

// Calls visit(i, j) once for every pair of `entries` of different instances whose boxes
// overlap, with positive extents in x and y (indices into `entries`, in either order).
void overlapping_entries(const std::vector<PlaneEntry>& entries,
                         const std::function<void(uint32_t, uint32_t)>& visit);

}  // namespace ds::scene::detail
