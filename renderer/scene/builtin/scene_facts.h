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
// alphaCutoff c exactly the part u >= c of each card survives.
constexpr float kFoliageAlphaCutoff = 0.5f;

}  // namespace ds::scene::builtin::facts
