#pragma once
// Geometry fix-ups the importer applies when a file leaves attributes out. Pure functions on
// Scene vertices, so tests can check them without a glTF file.
#include <cstdint>
#include <vector>

#include "renderer/scene/scene.h"

namespace ds::scene::detail {

// Gives every triangle its own three vertices carrying the face normal (a mesh without normals
// is drawn faceted, as glTF requires), and rewrites `indices` to 0..n-1.
void unweld_flat_normals(std::vector<Vertex>& vertices, std::vector<uint32_t>& indices);

// Per-vertex tangents from positions, normals and UV0 (Lengyel's method: accumulate the
// per-triangle UV gradient, then Gram-Schmidt against the normal). A vertex whose UVs give no
// usable gradient gets an arbitrary unit tangent perpendicular to its normal, never NaN.
// Handedness follows glTF: cross(normal, tangent) * w points to decreasing v (image "up").
void generate_tangents(std::vector<Vertex>& vertices, const std::vector<uint32_t>& indices);

Bounds compute_bounds(const std::vector<Vertex>& vertices);

// World-space box around `local` transformed by `world` (its eight corners).
Bounds transform_bounds(const Bounds& local, const glm::mat4& world);

}  // namespace ds::scene::detail
