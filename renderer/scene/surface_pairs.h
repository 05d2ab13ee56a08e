#pragma once
// Surfaces of two instances that share depth (what `depthscope lint` reports as coplanar
// overlaps, duplicate instances and near-coplanar fights), and degenerate triangles. Pure CPU
// geometry on the scene model: the caller names them and turns gaps into fight distances per
// depth format (renderer/view/precision.h).
//
// The rules. Work is in double precision, in world space (Instance::world), on pairs of
// triangles of two DIFFERENT instances (a < b; an instance never pairs with itself); a
// degenerate triangle (below) never pairs.
// - Facing: a triangle's normal is its winding's (cross(p1 - p0, p2 - p0)), turned over when
//   its instance's transform mirrors (negative determinant), as the rasteriser's front face is.
//   Two triangles face the same way when their normals lie within kPairFacingDegrees; anti-
//   parallel within that angle counts too when either instance's material is double-sided.
// - Overlap: b's triangle is projected along a's normal onto a's plane and clipped against a's
//   (Sutherland-Hodgman). It counts when it is wider than eps: twice its area over its
//   perimeter (its mean width) above eps at its centre, so tiles meeting at an edge, touching
//   corners and a closed box's faces are never pairs. The overlap is seen along the normal,
//   not from a camera: two parallel quads whose gap is large against their size can overlap
//   on screen and not along the normal (zfight: one of its six default slots has no near pair).
// - Gap: at every vertex q of the overlap, the signed distance along a's normal from a's plane
//   to b's; eps there is overlay_epsilon(q, L) (decals.h), L the longer of the two triangles'
//   longest edges. The triangle pair is COPLANAR when |gap| <= eps at every vertex; NEAR when
//   the gap has one sign with |gap| > eps at every vertex and its least |gap| is at most
//   `near_gap_max` (the closest part fights; max_gap may exceed it). A pair whose gap changes
//   sign or comes within eps at some vertex but not all (planes that cross or touch inside the
//   overlap) is neither.
// - Duplicate: two instances whose world triangles match vertex for vertex (same index count,
//   each corner within eps of its twin, same order; the same mesh under equal matrices, or a
//   copied mesh) are a DUPLICATE pair instead of a coplanar one; a duplicate pair reports no
//   near pair either (those are the mesh's own layers, seen twice).
// - Aggregation: one SurfacePair per instance pair and kind, sorted by (a, b, kind).
//   overlap_area sums the triangle pairs' overlaps (exact when neither instance overlaps
//   itself; more when one does); min_gap / max_gap are the least / greatest |gap| over the
//   overlap vertices of its triangle pairs (0 for Coplanar and Duplicate); normal, point and
//   triangle_a / triangle_b describe its largest triangle overlap (a's normal; a point inside
//   that overlap, on a's plane).
//
// Cost: triangles are binned by direction (a grid over unit normals, folded so n and -n share
// bins), then each direction bin is searched in its own frame: a 2-D grid in the plane, one
// level per factor 4 of triangle size, each cell's triangles swept in order of their offset
// along the normal. Parallel triangles that are far apart along their normal (stacked floors,
// the two sides of a city of boxes), side by side in the plane (tiled floors) or of very
// different sizes are never compared: the work is about linear in the triangles, plus the
// triangle pairs that do lie within the gap of each other (a large near_gap_max makes many).
// 2M triangles take about 1.5 s on one core.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/scene/scene.h"

namespace ds::scene {

inline constexpr double kPairFacingDegrees = 5.0;

struct SurfacePairOptions {
    double near_gap_max = 0.0;  // scene units; 0: no Near pairs
};

enum class PairKind : uint8_t { Coplanar, Duplicate, Near };
const char* to_string(PairKind kind);

struct SurfacePair {
    uint32_t a = 0, b = 0;  // indices into `instances`, a < b
    PairKind kind = PairKind::Coplanar;
    double overlap_area = 0.0;                // world units^2, summed over triangle pairs (above)
    double min_gap = 0.0, max_gap = 0.0;      // |gap| along the normal (0 unless Near)
    uint32_t triangle_pairs = 0;              // overlapping triangle pairs of this kind
    glm::dvec3 normal{0.0};                   // a's facing normal, at the largest overlap
    glm::dvec3 point{0.0};                    // world point inside it, on a's plane
    uint32_t triangle_a = 0, triangle_b = 0;  // triangle indices (mesh index / 3) of it
};

std::vector<SurfacePair> find_surface_pairs(const std::vector<Mesh>& meshes,
                                            const std::vector<Material>& materials,
                                            const std::vector<Instance>& instances,
                                            const SurfacePairOptions& options = {});

// Degenerate triangles. A triangle is degenerate when an index repeats or lies outside the
// vertices, or its area is at most kDegenerateArea times its longest edge squared (zero-length
// edges, collinear corners, non-finite positions): its height is then at most 2e-7 of that
// edge, about the float precision of its own corners, so its normal is rounding noise and it
// covers next to nothing. Counted per mesh in object space (instances do not multiply it).
inline constexpr double kDegenerateArea = 1e-7;
bool degenerate_triangle(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2);

struct DegenerateTriangles {
    uint32_t mesh = 0;   // index into `meshes`
    uint32_t count = 0;  // its degenerate triangles (> 0)
    uint32_t first = 0;  // the first one's triangle index (index / 3)
};
// Meshes with at least one degenerate triangle, in mesh order.
std::vector<DegenerateTriangles> find_degenerate_triangles(const std::vector<Mesh>& meshes);

}  // namespace ds::scene
