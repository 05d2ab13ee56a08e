#version 460
// zfight: every opaque and masked fragment drawn again over the prepass result, tested early
// (closer-or-equal, read-only) against zfight_bound: the stored depth moved zfight_steps + 1
// steps towards far, so hidden layers never run this shader.
// A fragment of another surface than the pixel's winner (surface_id) that passes its alpha
// test competes when its depth lies within push.max_steps representable steps of the stored
// depth (D32_SFLOAT: ULPs of the float; D24 / D16: unorm steps). Each competitor adds one to
// the pixel's count and appends (pixel, winner, competitor, steps and gap) for the report:
// the gap in scene units along the view ray as a float with its low 11 mantissa bits
// replaced by the steps (at most 1024).
// PER_SAMPLE=1 (msaa > 1): the pass runs multisampled against a per-sample zfight_bound and
// this shader runs once per sample (it reads gl_SampleID, which turns sample shading on):
// each sample's fragment depth (gl_FragCoord at the sample) is compared with that sample's
// stored depth and winner (msaa_depth, msaa_surface_id). The count image stays per pixel and
// sums the competing samples; records name the pixel, so pairs count distinct pixels.
#extension GL_GOOGLE_include_directive : require

#ifndef PER_SAMPLE
#define PER_SAMPLE 0
#endif

#include "common/bindings.glsl"

// The prepass vertex shader's outputs, all declared so the interfaces match.
layout(early_fragment_tests) in;

layout(location = 0) in vec3 in_world_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_uv0;
layout(location = 3) in vec4 in_tangent;
layout(location = 4) flat in uint in_surface_base;

#if PER_SAMPLE
layout(set = 2, binding = 0) uniform usampler2DMS surface_ids;
layout(set = 2, binding = 1) uniform sampler2DMS stored_depth;
#define STORED_SAMPLE gl_SampleID
#else
layout(set = 2, binding = 0) uniform usampler2D surface_ids;
layout(set = 2, binding = 1) uniform sampler2D stored_depth;
#define STORED_SAMPLE 0  // the level
#endif
layout(set = 2, binding = 2, r32ui) uniform uimage2D competitors;
layout(set = 2, binding = 3, std430) buffer Records {
    uint count;  // appended; past push.capacity the records are dropped (and counted)
    uint pad0, pad1, pad2;
    uvec4 records[];  // pixel index, winner id, competitor id, gap bits | steps
}
fights;

layout(push_constant) uniform Push {
    uint max_steps;
    uint depth_bits;  // 32: float, 24 / 16: unorm
    uint width;
    uint capacity;  // records[] length
}
push;

const uint kStepsMask = 0x7ffu;  // zfight_steps <= 1024

uint depth_steps(float a, float b) {
    if (push.depth_bits == 32u) {
        // Depths in [0, 1] are non-negative floats: their bit patterns order like the values.
        return uint(abs(int(floatBitsToUint(a)) - int(floatBitsToUint(b))));
    }
    const float levels = push.depth_bits == 24u ? 16777215.0 : 65535.0;
    return uint(abs(int(round(a * levels)) - int(round(b * levels))));
}

void main() {
    const ivec2 p = ivec2(gl_FragCoord.xy);
    const uint winner = texelFetch(surface_ids, p, STORED_SAMPLE).r;
    const uint me = in_surface_base + uint(gl_PrimitiveID) + 1u;
    if (winner == 0u || winner == me) return;
    if ((material.flags & kMaterialAlphaMask) != 0u) {
        const float sampled =
            texture(base_color_texture, texture_uv(kTextureBaseColor, in_uv0)).a;
        const float alpha = mask_alpha(in_uv0, sampled * material.base_color_factor.a);
        if (alpha < alpha_cutoff()) return;
    }
    const float stored = texelFetch(stored_depth, p, STORED_SAMPLE).r;
    const uint steps = depth_steps(stored, gl_FragCoord.z);
    if (steps > push.max_steps) return;
    imageAtomicAdd(competitors, p, 1u);
    const uint i = atomicAdd(fights.count, 1u);
    if (i >= push.capacity) return;
    const vec2 ndc = gl_FragCoord.xy * frame.viewport.zw * 2.0 - 1.0;
    const float gap = abs(gl_FragCoord.z - stored) * ray_units_per_depth(stored, ndc);
    const uint packed = (floatBitsToUint(gap) & ~kStepsMask) | steps;
    fights.records[i] = uvec4(uint(p.y) * push.width + uint(p.x), winner, me, packed);
}
