#version 460
#extension GL_GOOGLE_include_directive : require
// Edge-aware spatial filter of gtao's output: a separable 5-tap tent (1 2 2 2 1: equal weight
// per residue mod 4, so the product averages gtao's 4x4 rotation pattern out exactly), run
// twice: horizontally (ao_raw -> intermediate, VERTICAL 0), then vertically (-> ao_filtered,
// VERTICAL 1). Each tap is weighted by
//  - its distance from the centre pixel's tangent plane, relative to the view distance: taps
//    across a depth discontinuity get no weight, taps along a surface seen at a grazing angle
//    keep theirs however much their depth differs;
//  - the agreement of normals (dot^8): the floor does not borrow the wall's AO at a corner.
// Separable: 10 taps instead of 25, and texel fetches are what lavapipe pays for.
//
// When ao_raw has a lower resolution the same code upsamples (joint bilateral): the
// horizontal pass writes full width x raw height, the vertical one full resolution, and each
// input texel is judged through the full-resolution pixel it stands for (ao_source_pixel).

#ifndef VERTICAL
#define VERTICAL 0
#endif

layout(local_size_x = 8, local_size_y = 8) in;

#include "common/frame.glsl"
#include "common/screen_space.glsl"

layout(set = 1, binding = 0) uniform sampler2D depth_tex;
layout(set = 1, binding = 1) uniform sampler2D normal_tex;
layout(set = 1, binding = 2) uniform sampler2D ao_in;  // ao_raw, then the horizontal result
#if VERTICAL
layout(set = 1, binding = 3, r8) uniform writeonly image2D ao_out;
const ivec2 kAxis = ivec2(0, 1);
#else
layout(set = 1, binding = 3, r16f) uniform writeonly image2D ao_out;  // keeps values over 1
const ivec2 kAxis = ivec2(1, 0);
#endif

layout(push_constant) uniform Params {
    float plane_tolerance;  // tangent-plane distance (fraction of view distance) of weight 1/e
} params;

const float kTent[5] = float[5](1.0, 2.0, 2.0, 2.0, 1.0);

void main() {
    ivec2 o = ivec2(gl_GlobalInvocationID.xy);
    ivec2 out_size = imageSize(ao_out);
    if (any(greaterThanEqual(o, out_size))) return;
    ivec2 full_size = textureSize(depth_tex, 0);
    ivec2 in_size = textureSize(ao_in, 0);

    // The full-resolution pixel this output texel stands for (itself in the vertical pass).
    ivec2 px = ao_source_pixel(o, out_size, full_size);
    float d = texelFetch(depth_tex, px, 0).r;
    if (is_background(d)) {
        imageStore(ao_out, o, vec4(1.0));
        return;
    }
    vec3 n_world = decode_normal(texelFetch(normal_tex, px, 0).xyz);
    vec3 n_view = world_to_view_dir(n_world);
    // A tap's distance from this pixel's tangent plane, dot(ray_tap * z_tap - P, n), with the
    // tap's ray affine in its pixel offset (RayBasis): three dot products once, then per tap
    // z_tap * (r + ox * rx + oy * ry) - p.
    RayBasis rays = ray_basis(px, 1.0 / vec2(full_size));
    float r = dot(rays.ray, n_view), rx = dot(rays.dx, n_view), ry = dot(rays.dy, n_view);
    float p = r * linear_depth(d);
    float inv_tolerance = 1.0 / max(params.plane_tolerance * linear_depth(d), 1e-6);

    // The input texel nearest this one's centre (along the other axis the grids are equal).
    vec2 in_pos = (vec2(o) + 0.5) * vec2(in_size) / vec2(out_size) - 0.5;
    ivec2 base = clamp(ivec2(round(in_pos)), ivec2(0), in_size - 1);

    float sum = 0.0, weight_sum = 0.0;
    for (int k = -2; k <= 2; ++k) {
        ivec2 q = base + k * kAxis;
        if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, in_size))) continue;
        ivec2 s = ao_source_pixel(q, in_size, full_size);
        float ds = texelFetch(depth_tex, s, 0).r;
        if (is_background(ds)) continue;  // sky's AO is 1 by definition, not by geometry
        vec2 so = vec2(s - px);
        float plane = (linear_depth(ds) * (r + so.x * rx + so.y * ry) - p) * inv_tolerance;
        float c = max(dot(decode_normal(texelFetch(normal_tex, s, 0).xyz), n_world), 0.0);
        float c2 = c * c, c4 = c2 * c2;  // c^8: 1 on one plane, 0.3 at 30 degrees, 0 at 90
        float w = kTent[k + 2] * exp(-plane * plane) * c4 * c4;
        sum += w * texelFetch(ao_in, q, 0).r;
        weight_sum += w;
    }
    // No neighbour on this surface (a one-pixel feature): keep the nearest input value.
    float ao = weight_sum > 1e-4 ? sum / weight_sum : texelFetch(ao_in, base, 0).r;
#if VERTICAL
    ao = clamp(ao, 0.0, 1.0);  // raw values overshoot 1 (gtao.comp); their average does not
#endif
    imageStore(ao_out, o, vec4(ao));
}
