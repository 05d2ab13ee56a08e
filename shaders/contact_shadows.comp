#version 460
#extension GL_GOOGLE_include_directive : require
// Screen-space contact shadows: a short ray from each pixel's surface point towards the sun,
// marched against the prepass depth. The shadow map misses the small gaps where objects touch
// the ground (its texels and bias are larger than them); this catches them. A step is occluded
// when the ray point lies behind the visible surface by more than a small bias (depth
// precision) and less than `thickness` (surfaces are assumed that thick: a ray passing far
// behind a thin pole is not shadowed by it). Output 1 = lit, 0 = occluded.

#ifndef STEPS
#define STEPS 8
#endif

layout(local_size_x = 8, local_size_y = 8) in;

#include "common/frame.glsl"
#include "common/screen_space.glsl"

layout(set = 1, binding = 0) uniform sampler2D depth_tex;
layout(set = 1, binding = 1) uniform sampler2D normal_tex;
layout(set = 1, binding = 2, r8) uniform writeonly image2D shadow_out;

layout(push_constant) uniform Params {
    float ray_length;  // world-space length of the march (m)
    float thickness;   // assumed thickness of what the depth buffer shows (m)
    float bias;        // fraction of the view distance: normal offset and depth slack
} params;

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(shadow_out);
    if (any(greaterThanEqual(px, size))) return;
    ivec2 full_size = textureSize(depth_tex, 0);
    vec2 inv_size = 1.0 / vec2(full_size);

    float d = texelFetch(depth_tex, px, 0).r;
    if (is_background(d)) {
        imageStore(shadow_out, px, vec4(1.0));
        return;
    }
    vec3 P = view_position_at(px, inv_size, d);
    vec3 N = world_to_view_dir(decode_normal(texelFetch(normal_tex, px, 0).xyz));
    vec3 L = world_to_view_dir(frame.sun_direction.xyz);
    // Facing away from the sun: N.L already darkens it; marching would only find the surface
    // itself.
    if (dot(N, L) <= 0.0) {
        imageStore(shadow_out, px, vec4(1.0));
        return;
    }
    float slack = params.bias * -P.z;  // depth precision and pixel footprint grow with distance
    vec3 origin = P + N * slack;       // off the surface, so it does not shadow itself
    // Homogeneous clip coordinates are linear along a view-space segment: each step is a lerp
    // and a divide, and clip.w is the ray point's view distance.
    vec4 clip_start = frame.projection * vec4(origin, 1.0);
    vec4 clip_end = frame.projection * vec4(origin + L * params.ray_length, 1.0);
    // Per-pixel start offset (deterministic): banding from the fixed step turns into noise.
    float jitter = interleaved_gradient_noise(vec2(px));
    // Only x, y and w are needed; pixels = (xy / w * 0.5 + 0.5) * size = xy * scale / w + half.
    vec3 start = vec3(clip_start.xy * 0.5 * vec2(full_size), clip_start.w);
    vec3 step = vec3(clip_end.xy * 0.5 * vec2(full_size), clip_end.w) - start;
    vec2 half_size = 0.5 * vec2(full_size);
    LinearDepth depth_consts = linear_depth_consts();
    float lit = 1.0;
    for (int i = 0; i < STEPS; ++i) {
        vec3 clip = start + step * ((float(i) + jitter) / float(STEPS));
        if (clip.z <= 0.0) break;  // behind the camera
        ivec2 q = ivec2(floor(clip.xy / clip.z + half_size));
        if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, full_size))) break;
        float dq = texelFetch(depth_tex, q, 0).r;
        if (is_background(dq)) continue;
        // > 0: the ray is behind the visible surface
        float behind = clip.z - linear_depth(depth_consts, dq);
        if (behind > slack && behind < params.thickness) {
            lit = 0.0;
            break;
        }
    }
    imageStore(shadow_out, px, vec4(lit));
}
