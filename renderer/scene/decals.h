#pragma once
// Coplanar overlays (seed 004). Sponza's layered meshes lie on the wall under them with the
// wall's own vertices, so both pass the forward pass's EQUAL depth test and the pixel is
// composited twice. The importer classifies every scene (files and built-ins alike) at load,
// whatever the renderer's settings, so the renderer can draw the overlays once in their own
// pass (Scene::decals, DrawGroup::decal).
//
// The rule. Instance O lies on instance B (B != O) when B's triangles cover every
// non-degenerate world-space triangle of O: each of 16 sample points of the triangle (its
// vertices, edge midpoints and centroid; points 1% of the way from each vertex and midpoint
// towards the centroid; points halfway from each vertex to the centroid) lies within eps of the
// plane of a non-degenerate triangle of B and inside that triangle grown by eps in its plane.
// At a sample point p of a triangle whose longest edge is L, eps = kOverlayTolerance *
// (max_i |p_i| + L): relative to the geometry's own magnitude, never to the scene's size, so a
// quad 1e-4 m behind another at 1 m (or 50 m behind at 5 km) is a near Z-fight, not an overlay.
//
// O is a decal when it lies on some B that does not also lie on O: mutual cover (a duplicated
// mesh or instance, two identical surfaces) is a Z-fight, never a decal, and surfaces that
// merely overlap lie on neither. Alpha mode and double-sidedness play no part. O's base is,
// among the non-decal instances reached from O through "lies on" links (O1 on O2 on a wall:
// both get the wall), the one with the largest world area, then the lowest index; an O that
// reaches none (only a cycle of mutual near-covers) is not a decal. A mesh without
// non-degenerate triangles is never an overlay nor a base. Cover is sampled, not exact: a hole
// in B that no sample point of O falls into goes unseen.
//
// Cost: candidates B are those whose world bounds, grown by O's largest eps, hold O's bounds
// (found through a grid over instance bounds); each candidate's triangles go into a grid once,
// so the test is about linear in the triangles of overlay candidates.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/scene/scene.h"

namespace ds::scene {

inline constexpr double kOverlayTolerance = 1e-5;

// Buried overlays. Instance O (no decal) lies buried under instance B when each sample point
// of each of O's triangles lies behind the plane of a triangle of B that faces the way O's
// triangle does (normals within 5 degrees): more than eps behind it (so not on it) and at most
// kBuriedTolerance * (max_i |p_i| + L) behind, inside that triangle grown by the same amount.
// Wherever B is drawn, O is hidden by a gap a depth test resolves: no Z-fight, the overlay
// is simply gone. A lossy compressor makes this (gltf-pipeline's default Draco positions move
// a wall's face 1.2 mm towards the room, in front of the posters that lay on it); so does
// a surface modelled just under another. The base is the candidate with the least gap, then
// the lowest index.
inline constexpr double kBuriedTolerance = 1e-3;

struct OverlayClasses {
    std::vector<int32_t> decal_base;    // per instance, as find_decal_bases
    std::vector<BuriedOverlay> buried;  // indices into `instances`; gap: O's farthest sample
};
OverlayClasses classify_overlays(const std::vector<Mesh>& meshes,
                                 const std::vector<Instance>& instances);

// eps at world point `p` of a triangle whose longest edge is `longest_edge` (see above).
double overlay_epsilon(const glm::dvec3& p, double longest_edge);

// For each of `instances` (placing `meshes` in world space, in any order): the index into
// `instances` of the base it lies on as a decal, or -1 when it is not a decal.
std::vector<int32_t> find_decal_bases(const std::vector<Mesh>& meshes,
                                      const std::vector<Instance>& instances);

}  // namespace ds::scene
