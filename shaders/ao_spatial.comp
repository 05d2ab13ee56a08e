#version 460
#extension GL_GOOGLE_include_directive : require
// Edge-aware spatial filter of gtao's output, at gtao's resolution: a separable 5-tap tent
// (1 2 2 2 1: equal weight per residue mod 4, so the product averages gtao's 4x4 rotation
// pattern out exactly), run twice: horizontally (ao_raw -> ao_spatial_h, VERTICAL 0), then
// vertically (-> ao_filtered, VERTICAL 1). Each tap is weighted by
//  - its distance from the centre texel's tangent plane, relative to the view distance: taps
//    across a depth discontinuity get no weight, taps along a surface seen at a grazing angle
//    keep theirs however much their depth differs;
//  - the agreement of normals (dot^8): the floor does not borrow the wall's AO at a corner.
// Every image here is packed (AO, view distance, octahedral view-space normal) as gtao wrote
// it for the full-resolution pixel the texel stands for (ao_source_pixel), so a tap is one
// texel fetch: texel fetches are what lavapipe pays for. ao_temporal upsamples the result.

#ifndef VERTICAL
#define VERTICAL 0
#endif

layout(local_size_x = 8, local_size_y = 8) in;

#include "common/frame.glsl"
#include "common/screen_space.glsl"

layout(set = 1, binding = 0) uniform sampler2D ao_in;  // ao_raw, then the horizontal result
layout(set = 1, binding = 1, rgba16f) uniform writeonly image2D ao_out;
#if VERTICAL
const ivec2 kAxis = ivec2(0, 1);
#else
const ivec2 kAxis = ivec2(1, 0);
#endif

layout(push_constant) uniform Params {
    float plane_tolerance;  // tangent-plane distance (fraction of view distance) of weight 1/e
} params;

const float kTent[5] = float[5](1.0, 2.0, 2.0, 2.0, 1.0);

void main() {
    ivec2 o = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(ao_out);
    if (any(greaterThanEqual(o, size))) return;
    vec4 centre = texelFetch(ao_in, o, 0);
    if (!(centre.y > 0.0)) {  // sky: AO 1 by definition; distance 0 marks it
        imageStore(ao_out, o, vec4(1.0, 0.0, 0.0, 0.0));
        return;
    }
    ivec2 full_size = ivec2(frame.viewport.xy);
    vec3 n = oct_decode(centre.zw);
    // A tap's distance from this texel's tangent plane, dot(ray_tap * z_tap - P, n), with the
    // tap's ray affine in its full-resolution pixel offset (RayBasis): three dot products
    // once, then per tap z_tap * (r + ox * rx + oy * ry) - p.
    ivec2 px = ao_source_pixel(o, size, full_size);
    RayBasis rays = ray_basis(px, frame.viewport.zw);
    float r = dot(rays.ray, n), rx = dot(rays.dx, n), ry = dot(rays.dy, n);
    float p = r * centre.y;
    float inv_tolerance = 1.0 / max(params.plane_tolerance * centre.y, 1e-6);

    float sum = 0.0, weight_sum = 0.0;
    for (int k = -2; k <= 2; ++k) {
        ivec2 q = o + k * kAxis;
        if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
        vec4 tap = texelFetch(ao_in, q, 0);
        if (!(tap.y > 0.0)) continue;  // sky's AO is 1 by definition, not by geometry
        vec2 so = vec2(ao_source_pixel(q, size, full_size) - px);
        float plane = (tap.y * (r + so.x * rx + so.y * ry) - p) * inv_tolerance;
        float c = max(dot(oct_decode(tap.zw), n), 0.0);
        float c2 = c * c, c4 = c2 * c2;  // c^8: 1 on one plane, 0.3 at 30 degrees, 0 at 90
        float w = kTent[k + 2] * exp(-plane * plane) * c4 * c4;
        sum += w * tap.x;
        weight_sum += w;
    }
    // The centre itself always weighs 2 (plane 0, c 1), so weight_sum > 0.
    float ao = sum / weight_sum;
#if VERTICAL
    ao = clamp(ao, 0.0, 1.0);  // raw values overshoot 1 (gtao.comp); their average does not
#endif
    imageStore(ao_out, o, vec4(ao, centre.yzw));
}
