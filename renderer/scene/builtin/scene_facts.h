#pragma once
// Known facts of the synthetic built-in scenes, so tests can derive their expectations (counts,
// linear depths) from the same numbers the scenes are built from.
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
// error shows it) sits d_i * r_i behind the front one along the plane normal, r_i geometric
// from kZfightMinRelOffset to kZfightMaxRelOffset. Both go up together, so pairs that a 24-bit
// or forward-Z buffer merges still resolve with reverse-Z D32.
constexpr float kZfightZnear = 0.01f;
constexpr float kZfightZfar = 10000.0f;
constexpr float kZfightNearest = 1.0f;
constexpr float kZfightFarthest = 5000.0f;
constexpr float kZfightMinRelOffset = 1e-4f;
constexpr float kZfightMaxRelOffset = 1e-2f;

// foliage: every card's base-colour alpha is u (0 at the left edge, 1 at the right), so with
// alphaCutoff c exactly the part u >= c of each card survives.
constexpr float kFoliageAlphaCutoff = 0.5f;

}  // namespace ds::scene::builtin::facts
