#pragma once
// Known facts of the synthetic built-in scenes, so tests can derive their expectations (counts,
// linear depths) from the same numbers the scenes are built from.
#include <glm/glm.hpp>

namespace ds::scene::builtin::facts {

// overdraw: the camera sits at the origin looking down -Z with an identity rotation, so camera
// space is world space. Layer k (k = 0 is the nearest) is a quad in the plane
// z = -(kOverdrawNearestDepth + k * kOverdrawLayerSpacing), i.e. at linear depth 2, 3, 4, ...
// metres, for k = 0 .. overdraw_layers - 1. Every quad covers the whole view at any aspect up
// to 4:1. Nodes are authored farthest first (k = N-1 first), so each pixel is drawn N times.
constexpr float kOverdrawNearestDepth = 2.0f;
constexpr float kOverdrawLayerSpacing = 1.0f;
constexpr float overdraw_layer_depth(int k) {
    return kOverdrawNearestDepth + static_cast<float>(k) * kOverdrawLayerSpacing;
}

// zfight: the camera sits at the origin looking down -Z; znear/zfar are set in the glTF camera.
// Pair slot i (0 .. zfight_pairs-1) is centred at distance d_i, geometric from kZfightNearest
// to kZfightFarthest, and holds an exactly coplanar pair (same square, different diagonal) and
// a nearly coplanar pair whose back quad (80% of the front one's size, so only a depth-test
// error shows it) sits behind the front one, parallel to it, pushed back along the view ray
// through its centre by zfight_gap_metres(z), z the front quad's centre depth: there the two
// lie zfight_gap_steps(z) apart in a forward-Z 24-bit
// buffer (forward-Z D32_SFLOAT has the same steps there: ULPs of values in [0.5, 1)). Three
// classes, far from the zfight_steps default of 4 either way:
//   d < kZfightResolvedBelow: 8192 steps, resolved by every format (32 steps in D16);
//   d < kZfightD16MergesBelow: 64 steps, merged only by D16 (a quarter of a step there);
//   farther: half a step, merged by every forward-Z format, resolved by reverse-Z D32
//   (thousands of ULPs: reverse-Z float steps are relative to the distance).
constexpr float kZfightZnear = 0.01f;
constexpr float kZfightZfar = 10000.0f;
constexpr float kZfightNearest = 1.0f;
constexpr float kZfightFarthest = 5000.0f;
constexpr float kZfightResolvedBelow = 2.0f;
constexpr float kZfightD16MergesBelow = 200.0f;
constexpr float zfight_gap_steps(float d) {
    return d < kZfightResolvedBelow ? 8192.0f : d < kZfightD16MergesBelow ? 64.0f : 0.5f;
}
// The view-depth gap that many forward-Z 24-bit steps make at distance d: depth is
// f (z - n) / (z (f - n)), so d depth / dz = n f / (z^2 (f - n)).
constexpr float zfight_gap_metres(float d) {
    return zfight_gap_steps(d) / 16777215.0f * d * d * (kZfightZfar - kZfightZnear) /
           (kZfightZnear * kZfightZfar);
}

// foliage: every card's base-colour alpha is u (0 at the left edge, 1 at the right), so with
// alphaCutoff c exactly the part u >= c of each card survives. The far bushes (material grass)
// are thin blades instead, whose box-filtered mips lose coverage.
constexpr float kFoliageAlphaCutoff = 0.5f;

// decals: a room corner (seed 004's coplanar overlays). Three light-grey OPAQUE bases, each a
// grid of kDecalsCell cells: surface s has its cell (i, j) corner at origin + axis_u * (i * cell)
// + axis_v * (j * cell) and faces cross(axis_u, axis_v). Overlay k covers cells [i0, i1) x
// [j0, j1) of its surface, built the same way, so its vertices are bit-identical to the base's
// (the left wall and its overlay are authored in a local frame and placed by the same
// non-identity node transform). Its world rectangle is origin + s * edge_u + t * edge_v, s, t in
// [0, 1]; its UV u runs with s. A MASK overlay's texture has alpha 1 for u < kDecalsMaskKeep and
// 0 beyond (cutoff kDecalsMaskCutoff), so exactly its part s < kDecalsMaskKeep survives; the
// BLEND overlay's alpha is kDecalsBlendAlpha. Colours are base colour factors (linear). The
// camera sees every overlay whole at 16:9. No two bases are coplanar; overlays never overlap.
struct DecalsSurface {
    const char* node;  // node and mesh name
    glm::vec3 origin;
    glm::vec3 axis_u;  // unit
    glm::vec3 axis_v;  // unit
    int cells_u;
    int cells_v;
};
constexpr float kDecalsCell = 0.5f;
constexpr DecalsSurface kDecalsSurfaces[] = {
    {"back_wall", {-3, 0, -3}, {1, 0, 0}, {0, 1, 0}, 12, 6},  // z = -3, faces +Z
    {"left_wall", {-3, 0, 3}, {0, 0, -1}, {0, 1, 0}, 12, 6},  // x = -3, faces +X
    {"floor", {-3, 0, 3}, {1, 0, 0}, {0, 0, -1}, 12, 12},     // y = 0, faces +Y
};
constexpr glm::vec3 kDecalsBaseColour{0.7f, 0.7f, 0.7f};

enum class DecalsAlpha { Opaque, Mask, Blend };
struct DecalsOverlay {
    const char* node;  // node and mesh name
    int surface;       // index into kDecalsSurfaces: the base it lies on
    int i0, i1, j0, j1;
    DecalsAlpha alpha;
    glm::vec3 colour;
};
constexpr DecalsOverlay kDecalsOverlays[] = {
    {"decal_red_opaque", 0, 1, 5, 2, 4, DecalsAlpha::Opaque, {1, 0, 0}},
    {"decal_green_mask", 0, 7, 11, 2, 4, DecalsAlpha::Mask, {0, 1, 0}},
    {"decal_yellow_opaque", 2, 2, 5, 3, 6, DecalsAlpha::Opaque, {1, 1, 0}},
    {"decal_magenta_mask", 2, 7, 11, 4, 7, DecalsAlpha::Mask, {1, 0, 1}},
    {"decal_blue_blend", 1, 3, 8, 2, 4, DecalsAlpha::Blend, {0, 0, 1}},
};
constexpr float kDecalsMaskKeep = 0.5f;
constexpr float kDecalsMaskCutoff = 0.5f;
constexpr float kDecalsBlendAlpha = 0.5f;

struct DecalsRect {
    glm::vec3 origin;
    glm::vec3 edge_u;
    glm::vec3 edge_v;
};
constexpr DecalsRect decals_overlay_rect(const DecalsOverlay& o) {
    const DecalsSurface& s = kDecalsSurfaces[o.surface];
    return {s.origin + s.axis_u * (kDecalsCell * static_cast<float>(o.i0)) +
                s.axis_v * (kDecalsCell * static_cast<float>(o.j0)),
            s.axis_u * (kDecalsCell * static_cast<float>(o.i1 - o.i0)),
            s.axis_v * (kDecalsCell * static_cast<float>(o.j1 - o.j0))};
}

}  // namespace ds::scene::builtin::facts
