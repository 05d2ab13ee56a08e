#version 460
// depth_precision: per pixel, how far along the view ray the next representable depth value
// lies from the stored one, in scene units (r), and the distance along that ray (g), for the
// frame's depth format, planes and direction (b, a: 0): one step of the format (ULP of the
// float for D32, the next float towards far; one unorm step for D24 / D16) times
// ray_units_per_depth (common/frame.glsl).
#extension GL_GOOGLE_include_directive : require

#include "common/frame.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 1, binding = 0) uniform sampler2D stored_depth;
layout(set = 1, binding = 1, rgba32f) uniform writeonly image2D precision_out;

layout(push_constant) uniform Push {
    uint depth_bits;  // 32: float, 24 / 16: unorm
}
push;

float step_of(float d) {
    if (push.depth_bits == 32u) {
        // Towards far: reverse-Z far is 0 (the smaller float), forward-Z far is 1.
        const bool reverse = frame.depth_params.z > 0.5;
        const uint bits = floatBitsToUint(d);
        const float next = uintBitsToFloat(reverse ? max(bits, 1u) - 1u : bits + 1u);
        return abs(next - d);
    }
    return 1.0 / (push.depth_bits == 24u ? 16777215.0 : 65535.0);
}

void main() {
    const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(precision_out)))) return;
    const float d = texelFetch(stored_depth, p, 0).r;
    const bool reverse = frame.depth_params.z > 0.5;
    if (d == (reverse ? 0.0 : 1.0)) {  // sky: nothing stored
        imageStore(precision_out, p, vec4(0.0));
        return;
    }
    const vec2 ndc = (vec2(p) + 0.5) / vec2(imageSize(precision_out)) * 2.0 - 1.0;
    const vec4 view = frame.inverse_projection * vec4(ndc, d, 1.0);
    const float distance = length(view.xyz / view.w);
    imageStore(precision_out, p, vec4(step_of(d) * ray_units_per_depth(d, ndc), distance, 0.0, 0.0));
}
