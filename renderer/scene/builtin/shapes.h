#pragma once
// Triangle-mesh generators for the built-in scenes. Every generator returns counter-clockwise
// front faces (glTF convention), unit normals and UVs; tangents are derived by the builder.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace ds::scene::builtin {

struct MeshData {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;
    std::vector<uint32_t> indices;

    uint32_t vertex_count() const { return static_cast<uint32_t>(positions.size()); }
    uint32_t add_vertex(const glm::vec3& p, const glm::vec3& n, const glm::vec2& uv);
    // Two triangles (a, b, c) and (a, c, d); a..d counter-clockwise seen from the front.
    void add_quad(uint32_t a, uint32_t b, uint32_t c, uint32_t d);
    // Appends `other` transformed by `m` (normals by its inverse transpose).
    void append(const MeshData& other, const glm::mat4& m = glm::mat4(1.0f));
};

// Per-vertex tangents (xyz, w = handedness) from positions, normals and UVs.
std::vector<glm::vec4> compute_tangents(const MeshData& mesh);

// Quad in the XY plane centred on the origin, facing +Z; UV (0,0) at the top-left corner.
MeshData make_quad(glm::vec2 size, glm::vec2 uv_scale = {1.0f, 1.0f});

// Axis-aligned box. UVs repeat every 1/uv_per_meter metres (0: each face maps 0..1).
// `skip_faces` is a bit mask of faces to leave out: see kFace* below.
constexpr uint32_t kFaceNegX = 1, kFacePosX = 2, kFaceNegY = 4, kFacePosY = 8, kFaceNegZ = 16,
                   kFacePosZ = 32;
MeshData make_box(const glm::vec3& min, const glm::vec3& max, float uv_per_meter = 0.0f,
                  uint32_t skip_faces = 0);

// Truncated cone along +Y from y=0 to `height`, with caps (a cylinder when radii are equal).
MeshData make_frustum(float r_bottom, float r_top, float height, int segments, float uv_v = 1.0f);

// A planar grid of cells: vertex (i, j) sits at origin + axis_u*(i*cell.x) + axis_v*(j*cell.y),
// computed the same way for every call. A decal made of a sub-range of a wall's cells therefore
// has bit-identical vertices and triangles (same diagonals) to the wall under it, which is what
// makes it pass an EQUAL depth test exactly as seed 004 describes. The front face is
// cross(axis_u, axis_v). UVs: uv_per_meter > 0 maps by distance; 0 maps the range to 0..1.
struct GridRange {
    int i0 = 0, i1 = 1, j0 = 0, j1 = 1;
};
MeshData make_grid(const glm::vec3& origin, const glm::vec3& axis_u, const glm::vec3& axis_v,
                   glm::vec2 cell, GridRange range, float uv_per_meter);

// Arch block between two column centres: x in [-span/2, span/2], y in [0, height] (y=0 is the
// springing line), z in [-depth/2, depth/2], with a semicircular opening of `radius` centred on
// the origin.
MeshData make_arch(float span, float height, float depth, float radius, int segments);

// Hanging cloth: top edge at y=0, hangs to -height, folds along x as a sine of amplitude `amp`
// (in z); spans x in [-width/2, width/2].
MeshData make_curtain(float width, float height, int folds, float amp);

// Crossed vertical cards around +Y (a bush), plus `tilted` cards leaning outwards.
MeshData make_plant_cards(float radius, float height, int cards, int tilted);

}  // namespace ds::scene::builtin
