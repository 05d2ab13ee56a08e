// The triangle-pair test of find_surface_pairs (surface_pairs.h): facing, the overlap of b
// projected onto a's plane (a 2-D Sutherland-Hodgman clip), its width and the gaps at its
// vertices.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "renderer/scene/decals.h"
#include "renderer/scene/surface_pairs.h"
#include "renderer/scene/surface_pairs_detail.h"

namespace ds::scene {

bool degenerate_triangle(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2) {
    const double area = 0.5 * glm::length(glm::cross(p1 - p0, p2 - p0));
    const double longest =
        std::max({glm::length(p1 - p0), glm::length(p2 - p1), glm::length(p0 - p2)});
    // Also true for NaN and infinite corners (the comparison fails).
    return !(area > kDegenerateArea * longest * longest);
}

namespace detail {
namespace {

using glm::dvec2;
using glm::dvec3;

// A convex polygon in a's plane: a triangle clipped by three half-planes has at most 6
// corners; room for the transient extra corner of each step.
struct ClipPolygon {
    std::array<dvec2, 9> v;
    size_t n = 0;
    void push(const dvec2& p) { v[n++] = p; }
};

double clip_cross(const dvec2& a, const dvec2& b) {
    return a.x * b.y - a.y * b.x;
}

double clip_signed_area(const ClipPolygon& poly) {
    double twice = 0.0;
    for (size_t i = 0; i < poly.n; ++i) twice += clip_cross(poly.v[i], poly.v[(i + 1) % poly.n]);
    return 0.5 * twice;
}

// The part of `in` on the left of the directed line from `a` to `b` (Sutherland-Hodgman).
void clip_half_plane(const ClipPolygon& in, const dvec2& a, const dvec2& b, ClipPolygon& out) {
    out.n = 0;
    const dvec2 edge = b - a;
    for (size_t i = 0; i < in.n; ++i) {
        const dvec2& prev = in.v[(i + in.n - 1) % in.n];
        const dvec2& cur = in.v[i];
        const double dp = clip_cross(edge, prev - a);
        const double dc = clip_cross(edge, cur - a);
        if ((dp < 0.0) != (dc < 0.0)) out.push(prev + (cur - prev) * (dp / (dp - dc)));
        if (dc >= 0.0) out.push(cur);
    }
}

// The overlap of two counter-clockwise triangles.
ClipPolygon clip_triangles(const ClipPolygon& a, const ClipPolygon& b) {
    ClipPolygon poly = a, next;
    for (size_t k = 0; k < 3 && poly.n >= 3; ++k) {
        clip_half_plane(poly, b.v[k], b.v[(k + 1) % 3], next);
        poly = next;
    }
    return poly;
}

// Triangle `t` in the 2-D frame (origin, e1, e2) of a plane, counter-clockwise.
ClipPolygon clip_flatten(const WorldTriangle& t, const dvec3& origin, const dvec3& e1,
                         const dvec3& e2) {
    ClipPolygon poly;
    for (const dvec3& p : t.p) poly.push({glm::dot(p - origin, e1), glm::dot(p - origin, e2)});
    if (clip_signed_area(poly) < 0.0) std::swap(poly.v[1], poly.v[2]);
    return poly;
}

bool clip_boxes_apart(const ClipPolygon& a, const ClipPolygon& b) {
    dvec2 alo = a.v[0], ahi = a.v[0], blo = b.v[0], bhi = b.v[0];
    for (size_t i = 1; i < 3; ++i) {
        alo = glm::min(alo, a.v[i]);
        ahi = glm::max(ahi, a.v[i]);
        blo = glm::min(blo, b.v[i]);
        bhi = glm::max(bhi, b.v[i]);
    }
    return ahi.x < blo.x || bhi.x < alo.x || ahi.y < blo.y || bhi.y < alo.y;
}

// Gaps from a's plane to b's along a's normal at the overlap's vertices, classified.
TriangleContact clip_classify(const ClipPolygon& poly, const WorldTriangle& a,
                              const WorldTriangle& b, const dvec3 (&frame)[2],
                              double near_gap_max) {
    const double longest = std::max(a.longest, b.longest);
    const double along = glm::dot(a.n, b.n);  // |along| >= cos(5 degrees)
    bool within = true, above = true, below = true;
    TriangleContact c;
    c.min_gap = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < poly.n; ++i) {
        const dvec3 q = a.p[0] + frame[0] * poly.v[i].x + frame[1] * poly.v[i].y;
        const double gap = glm::dot(b.p[0] - q, b.n) / along;
        const double eps = overlay_epsilon(q, longest);
        within = within && std::abs(gap) <= eps;
        above = above && gap > eps;
        below = below && gap < -eps;
        c.min_gap = std::min(c.min_gap, std::abs(gap));
        c.max_gap = std::max(c.max_gap, std::abs(gap));
    }
    if (within) {
        c.kind = Contact::Coplanar;
        c.min_gap = c.max_gap = 0.0;
    } else if ((above || below) && c.min_gap <= near_gap_max) {
        c.kind = Contact::Near;
    }
    return c;
}

}  // namespace

bool world_triangle(const PairInstance& instance, uint32_t triangle, WorldTriangle& out) {
    if (instance.mesh == nullptr) return false;
    const std::vector<uint32_t>& indices = instance.mesh->indices;
    const size_t first = size_t{triangle} * 3;
    if (first + 2 >= indices.size()) return false;
    for (size_t k = 0; k < 3; ++k) {
        const uint32_t index = indices[first + k];
        if (index >= instance.mesh->vertices.size()) return false;
        out.p[k] = world_position(instance, index);
    }
    if (degenerate_triangle(out.p[0], out.p[1], out.p[2])) return false;
    out.n = glm::normalize(glm::cross(out.p[1] - out.p[0], out.p[2] - out.p[0])) * instance.facing;
    out.longest = std::max({glm::length(out.p[1] - out.p[0]), glm::length(out.p[2] - out.p[1]),
                            glm::length(out.p[0] - out.p[2])});
    return true;
}

TriangleContact triangle_contact(const WorldTriangle& a, const WorldTriangle& b,
                                 bool either_double_sided, double near_gap_max) {
    static const double kFacing = std::cos(glm::radians(kPairFacingDegrees));
    const double along = glm::dot(a.n, b.n);
    if (!(along >= kFacing || (either_double_sided && along <= -kFacing))) return {};
    const dvec3 e1 = glm::normalize(a.p[1] - a.p[0]);
    const dvec3 frame[2] = {e1, glm::cross(a.n, e1)};
    const ClipPolygon ta = clip_flatten(a, a.p[0], frame[0], frame[1]);
    const ClipPolygon tb = clip_flatten(b, a.p[0], frame[0], frame[1]);
    if (clip_boxes_apart(ta, tb)) return {};
    const ClipPolygon poly = clip_triangles(ta, tb);
    if (poly.n < 3) return {};
    double perimeter = 0.0;
    dvec2 centre(0.0);
    for (size_t i = 0; i < poly.n; ++i) {
        perimeter += glm::length(poly.v[(i + 1) % poly.n] - poly.v[i]);
        centre += poly.v[i] / static_cast<double>(poly.n);
    }
    const double area = clip_signed_area(poly);
    const dvec3 point = a.p[0] + frame[0] * centre.x + frame[1] * centre.y;
    // Narrower than eps: a shared edge or corner (surface_pairs.h).
    if (!(2.0 * area > perimeter * overlay_epsilon(point, std::max(a.longest, b.longest))))
        return {};
    TriangleContact c = clip_classify(poly, a, b, frame, near_gap_max);
    c.area = area;
    c.point = point;
    return c;
}

}  // namespace detail
}  // namespace ds::scene
