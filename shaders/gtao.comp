#version 460
#extension GL_GOOGLE_include_directive : require
// Ground-truth ambient occlusion (Jimenez et al. 2016, "Practical Realtime Strategies for
// Accurate Indirect Occlusion"), from the prepass depth and normals.
//
// Per AO texel: SLICES planes through the view vector, each rotated by a 4x4 pattern so that
// ao_spatial's 5x5 tent averages 16 rotations; in each slice, the highest horizon on both
// sides is found by marching STEPS depth samples over a world-space radius projected to
// pixels; the cosine-weighted visible arc between the two horizons is integrated analytically
// with the normal projected onto the slice. 1 = unoccluded.
//
// The output may be smaller than the depth buffer (GtaoPass's resolution scale): each texel
// stands for one full-resolution pixel (ao_source_pixel) and samples full-resolution depth.

#ifndef SLICES
#define SLICES 2  // slice directions per texel (x16 rotations after the spatial filter)
#endif
#ifndef STEPS
#define STEPS 4  // depth samples per side of a slice
#endif

layout(local_size_x = 8, local_size_y = 8) in;

#include "common/frame.glsl"
#include "common/screen_space.glsl"

layout(set = 1, binding = 0) uniform sampler2D depth_tex;   // prepass depth
layout(set = 1, binding = 1) uniform sampler2D normal_tex;  // world normals, n * 0.5 + 0.5
// Packed for ao_spatial and ao_temporal, whose taps are then one fetch each: r visibility, g
// view distance of the source pixel (0: sky), ba its view-space normal (oct_encode). Float,
// not UNORM: with few slices a pixel's visibility overshoots 1 as often as it falls short on
// an open plane (only the average over the 4x4 rotations is 1), so clamping before
// ao_spatial's average would bias open surfaces dark.
layout(set = 1, binding = 2, rgba16f) uniform writeonly image2D ao_out;

layout(push_constant) uniform Params {
    float radius;         // world-space radius (m) in which occluders count
    float falloff;        // fraction of the radius over which an occluder's weight fades to 0
    float max_radius_px;  // cap of the projected radius in full-resolution pixels
    float power;          // visibility ^ power (1 = physically based)
} params;

// The normal as one slice sees it: n is its signed angle from V in the slice plane.
struct Slice {
    float cos_n, sin_n;
    float inv_proj_len;  // 1 / length of the normal projected onto the slice plane
};

ivec2 g_full_size;
RayBasis g_rays;  // around the centre pixel
LinearDepth g_depth;
float g_falloff_mul, g_falloff_add;

// Cosine of the horizon angle (from V, in the slice) that pixel q sets on side `side` (+1:
// along omega, -1: against), or `low` (the tangent plane's horizon) where there is no usable
// sample. The angle is taken from the sample's elevation above the tangent plane, scaled into
// the slice (sin e' = dot(d, N) / |N projected on the slice|), not from dot(d, V): a sample
// snapped to a pixel centre lies slightly off the slice plane, and on a surface seen at a
// grazing angle dot(d, V) would then read a plane's own pixels as occluders half the time
// (a dark bias on open floors), while their elevation stays exactly 0. In-slice samples give
// the same angle either way. Occluders farther than the radius fade out, so distant geometry
// behind a silhouette does not darken the foreground.
float horizon_cos(ivec2 q, ivec2 src, vec3 P, vec3 N, Slice sl, float side, float low) {
    if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, g_full_size))) return low;
    float d = texelFetch(depth_tex, q, 0).r;
    vec3 delta = basis_ray(g_rays, vec2(q - src)) * linear_depth(g_depth, d) - P;  // sky: weight 0
    // One inverse square root gives both the distance and the normalisation.
    float dist2 = max(dot(delta, delta), 1e-12);
    float inv_dist = inversesqrt(dist2);
    float weight = clamp(dist2 * inv_dist * g_falloff_mul + g_falloff_add, 0.0, 1.0);
    float sin_e = clamp(dot(delta, N) * inv_dist * sl.inv_proj_len, -1.0, 1.0);
    float cos_e = sqrt(1.0 - sin_e * sin_e);
    // cos(n + side * (pi/2 - e)): the tangent's angle moved up by the elevation.
    float shc = sl.cos_n * sin_e - side * sl.sin_n * cos_e;
    return mix(low, shc, weight);
}

// Visible fraction of one slice: its horizons are searched in screen direction omega (pixels,
// x right, y down) and -omega.
float slice_visibility(vec2 omega, ivec2 src, vec3 P, vec3 V, vec3 N, float radius_px,
                       float jitter) {
    // The slice plane holds V and the view-space direction that projects onto omega: the
    // point one pixel along omega at the same depth gives it, whatever the projection.
    vec3 along = basis_ray(g_rays, omega) * -P.z - P;
    vec3 ortho = normalize(along - dot(along, V) * V);
    vec3 axis = cross(ortho, V);  // slice plane normal; unit because ortho is orthogonal to V
    vec3 proj_n = N - axis * dot(N, axis);
    float proj_len = length(proj_n);
    if (proj_len < 1e-4) return 1.0;  // normal along the slice normal: the slice sees nothing
    float cos_n = clamp(dot(proj_n, V) / proj_len, 0.0, 1.0);
    // n, the normal's signed angle from V (positive towards +omega), enters only through its
    // cosine and sine: no angle, no sin(acos()).
    float n_sign = dot(ortho, proj_n) < 0.0 ? -1.0 : 1.0;
    Slice sl = Slice(cos_n, n_sign * sqrt(1.0 - cos_n * cos_n), 1.0 / proj_len);

    // Start from the tangent plane: a surface never occludes itself.
    float low_pos = -sl.sin_n, low_neg = sl.sin_n;  // cos(n + pi/2), cos(n - pi/2)
    float hc_pos = low_pos, hc_neg = low_neg;
    float min_s = 1.3 / radius_px;  // the first sample lands on another pixel, not the centre
    vec2 centre = vec2(src) + 0.5;
    for (int i = 0; i < STEPS; ++i) {
        float s = (float(i) + jitter) / float(STEPS);
        s = s * s + min_s;  // denser near the centre, where occluders weigh most
        vec2 offset = omega * (s * radius_px);
        // Whole pixels: the reconstructed position then matches the depth texel exactly.
        hc_pos = max(hc_pos, horizon_cos(ivec2(floor(centre + offset)), src, P, N, sl, 1.0,
                                         low_pos));
        hc_neg = max(hc_neg, horizon_cos(ivec2(floor(centre - offset)), src, P, N, sl, -1.0,
                                         low_neg));
    }
    // Horizon angles from V (negative side first). The tangent-plane start keeps each within
    // the hemisphere around n (hc_pos >= cos(n + pi/2) gives h1 <= n + pi/2, and likewise
    // h0 >= n - pi/2), so no clamp to it is needed; h1 in [0, pi], h0 in [-pi, 0].
    hc_neg = clamp(hc_neg, -1.0, 1.0);
    hc_pos = clamp(hc_pos, -1.0, 1.0);
    float h0 = -fast_acos(hc_neg), h1 = fast_acos(hc_pos);
    float sin_h0 = -sqrt(1.0 - hc_neg * hc_neg), sin_h1 = sqrt(1.0 - hc_pos * hc_pos);
    // Closed form of the cosine-weighted arc integral (the paper's eq. 10), weighted by the
    // projected normal's length so the slices average to the hemisphere integral. Its
    // cos(2h - n) expanded through cos h, sin h, cos n, sin n: no library cosine per slice.
    float cos_2h0_n = (2.0 * hc_neg * hc_neg - 1.0) * cos_n + 2.0 * sin_h0 * hc_neg * sl.sin_n;
    float cos_2h1_n = (2.0 * hc_pos * hc_pos - 1.0) * cos_n + 2.0 * sin_h1 * hc_pos * sl.sin_n;
    float arc0 = cos_n + 2.0 * h0 * sl.sin_n - cos_2h0_n;
    float arc1 = cos_n + 2.0 * h1 * sl.sin_n - cos_2h1_n;
    return proj_len * 0.25 * (arc0 + arc1);
}

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    ivec2 ao_size = imageSize(ao_out);
    if (any(greaterThanEqual(px, ao_size))) return;
    g_full_size = textureSize(depth_tex, 0);

    ivec2 src = ao_source_pixel(px, ao_size, g_full_size);
    float d = texelFetch(depth_tex, src, 0).r;
    if (is_background(d)) {
        imageStore(ao_out, px, vec4(1.0, 0.0, 0.0, 0.0));  // sky is never occluded
        return;
    }
    g_rays = ray_basis(src, 1.0 / vec2(g_full_size));
    g_depth = linear_depth_consts();
    vec3 P = g_rays.ray * linear_depth(d);
    vec3 V = normalize(-P);
    vec3 N = world_to_view_dir(decode_normal(texelFetch(normal_tex, src, 0).xyz));

    // Pixels per metre at this distance (full resolution).
    float pixels_per_m = 0.5 * float(g_full_size.y) * abs(frame.projection[1][1]) / -P.z;
    float radius_px = min(params.radius * pixels_per_m, params.max_radius_px);
    vec4 packed_surface = vec4(1.0, -P.z, oct_encode(N));
    if (radius_px < 1.5) {  // the radius covers about one pixel: nothing to sample
        imageStore(ao_out, px, packed_surface);
        return;
    }
    float falloff_range = max(params.falloff * params.radius, 1e-4);
    g_falloff_mul = -1.0 / falloff_range;
    g_falloff_add = (params.radius - falloff_range) / falloff_range + 1.0;

    // Deterministic noise: same depth and normals, same AO (4x4 tile, see bayer4()).
    uint k = bayer4(px);
    float rotation = (float(k) + 0.5) / 16.0;
    float jitter = (float((k * 5u + 3u) & 15u) + 0.5) / 16.0;  // another order of the tile

    // Slice k's direction is at angle (k + rotation) * pi / SLICES: one sine and cosine for
    // the first, then a fixed rotation per slice.
    float phi = rotation * kPi / float(SLICES);
    vec2 omega = vec2(cos(phi), sin(phi));
    const float kStep = kPi / float(SLICES);
    const mat2 kNext = mat2(cos(kStep), sin(kStep), -sin(kStep), cos(kStep));
    float visibility = 0.0;
    for (int slice = 0; slice < SLICES; ++slice) {
        visibility += slice_visibility(omega, src, P, V, N, radius_px, jitter);
        omega = kNext * omega;
    }
    visibility = max(visibility / float(SLICES), 0.0);  // > 1 allowed, see ao_out
    if (params.power != 1.0) visibility = pow(visibility, params.power);
    packed_surface.x = visibility;
    imageStore(ao_out, px, packed_surface);
}
