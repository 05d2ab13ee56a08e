#version 460
// hiz_test: each instance's world box against the Hi-Z pyramid (renderer/passes/hiz.h), one
// invocation per instance. The box's eight corners through the frame's view_projection (the
// expression the prepass rasterises with) give a screen rectangle and the box's nearest depth;
// the rectangle's texels are followed up the pyramid (texel p of level k lies under texel
// min(p / 2, size - 1) of level k + 1, hiz.comp's rule) to the first level where it spans at
// most 2x2 texels, whose farthest depth is compared with the nearest. Occluded only when the
// box is farther by more than a margin (rounding between this and the rasteriser's vertex
// transform); a box with a corner behind the eye or in front of the near plane is visible (the
// test says nothing there); one whose corners all lie beyond one clip plane is outside.
// Out, per instance: verdict (0 visible, 1 occluded, 2 outside), the level read, the box's
// nearest depth and the pyramid's farthest (bit patterns).
#extension GL_GOOGLE_include_directive : require

#include "common/frame.glsl"

layout(local_size_x = 64) in;

layout(set = 1, binding = 0, std430) readonly buffer Boxes {
    vec4 boxes[];  // per instance: world min, world max
};
layout(set = 1, binding = 1, std430) writeonly buffer Verdicts {
    uvec4 verdicts[];
};
// The pyramid's levels, one binding each (unused ones repeat the last level).
layout(set = 1, binding = 2) uniform sampler2D level0;
layout(set = 1, binding = 3) uniform sampler2D level1;
layout(set = 1, binding = 4) uniform sampler2D level2;
layout(set = 1, binding = 5) uniform sampler2D level3;
layout(set = 1, binding = 6) uniform sampler2D level4;
layout(set = 1, binding = 7) uniform sampler2D level5;
layout(set = 1, binding = 8) uniform sampler2D level6;
layout(set = 1, binding = 9) uniform sampler2D level7;
layout(set = 1, binding = 10) uniform sampler2D level8;
layout(set = 1, binding = 11) uniform sampler2D level9;
layout(set = 1, binding = 12) uniform sampler2D level10;
layout(set = 1, binding = 13) uniform sampler2D level11;
layout(set = 1, binding = 14) uniform sampler2D level12;
layout(set = 1, binding = 15) uniform sampler2D level13;
layout(set = 1, binding = 16) uniform sampler2D level14;
layout(set = 1, binding = 17) uniform sampler2D level15;

layout(push_constant) uniform Push {
    uint instances;
    uint levels;
    float margin;  // relative
}
push;

const uint kVisible = 0u, kOccluded = 1u, kOutside = 2u;

float fetch(uint k, ivec2 p) {
    switch (k) {
        case 0u: return texelFetch(level0, p, 0).r;
        case 1u: return texelFetch(level1, p, 0).r;
        case 2u: return texelFetch(level2, p, 0).r;
        case 3u: return texelFetch(level3, p, 0).r;
        case 4u: return texelFetch(level4, p, 0).r;
        case 5u: return texelFetch(level5, p, 0).r;
        case 6u: return texelFetch(level6, p, 0).r;
        case 7u: return texelFetch(level7, p, 0).r;
        case 8u: return texelFetch(level8, p, 0).r;
        case 9u: return texelFetch(level9, p, 0).r;
        case 10u: return texelFetch(level10, p, 0).r;
        case 11u: return texelFetch(level11, p, 0).r;
        case 12u: return texelFetch(level12, p, 0).r;
        case 13u: return texelFetch(level13, p, 0).r;
        case 14u: return texelFetch(level14, p, 0).r;
        case 15u: return texelFetch(level15, p, 0).r;
    }
    return 0.0;
}

bool reverse_z() {
    return frame.depth_params.z > 0.5;
}

float farther(float a, float b) {
    return reverse_z() ? min(a, b) : max(a, b);
}

void finish(uint i, uint verdict, uint level, float nearest, float farthest) {
    verdicts[i] = uvec4(verdict, level, floatBitsToUint(nearest), floatBitsToUint(farthest));
}

void main() {
    const uint i = gl_GlobalInvocationID.x;
    if (i >= push.instances) return;
    const vec3 lo = boxes[2u * i].xyz, hi = boxes[2u * i + 1u].xyz;
    if (any(greaterThan(lo, hi))) {  // no geometry
        finish(i, kVisible, 0u, 0.0, 0.0);
        return;
    }
    const bool reverse = reverse_z();
    // Outside: every corner beyond one and the same clip plane (-w <= x, y <= w, 0 <= z <= w,
    // w > 0), so the whole box is (it is convex; this holds for corners behind the eye too).
    vec4 clip[8];
    bvec4 all_beyond_xy = bvec4(true);  // x > w, x < -w, y > w, y < -w
    bvec3 all_beyond_zw = bvec3(true);  // z > w, z < 0, w <= 0
    bool any_behind = false;
    for (int c = 0; c < 8; ++c) {
        const vec3 corner = vec3((c & 1) != 0 ? hi.x : lo.x, (c & 2) != 0 ? hi.y : lo.y,
                                 (c & 4) != 0 ? hi.z : lo.z);
        const vec4 v = frame.view_projection * vec4(corner, 1.0);
        clip[c] = v;
        all_beyond_xy = bvec4(all_beyond_xy.x && v.x > v.w, all_beyond_xy.y && v.x < -v.w,
                              all_beyond_xy.z && v.y > v.w, all_beyond_xy.w && v.y < -v.w);
        all_beyond_zw = bvec3(all_beyond_zw.x && v.z > v.w, all_beyond_zw.y && v.z < 0.0,
                              all_beyond_zw.z && !(v.w > 0.0));
        any_behind = any_behind || !(v.w > 0.0);
    }
    if (any(all_beyond_xy) || any(all_beyond_zw)) {
        finish(i, kOutside, 0u, 0.0, 0.0);
        return;
    }
    if (any_behind) {  // the box reaches behind the eye: the test says nothing
        finish(i, kVisible, 0u, 0.0, 0.0);
        return;
    }
    vec2 ndc_lo = vec2(1e30), ndc_hi = vec2(-1e30);
    float nearest = reverse ? -1e30 : 1e30;
    for (int c = 0; c < 8; ++c) {
        const vec3 ndc = clip[c].xyz / clip[c].w;
        ndc_lo = min(ndc_lo, ndc.xy);
        ndc_hi = max(ndc_hi, ndc.xy);
        nearest = reverse ? max(nearest, ndc.z) : min(nearest, ndc.z);
    }
    // In front of the near plane (the rasteriser clips it): the test says nothing.
    if (reverse ? nearest > 1.0 : nearest < 0.0) {
        finish(i, kVisible, 0u, nearest, 0.0);
        return;
    }
    // Pixels whose area the rectangle touches (a superset of the centres it covers).
    const ivec2 size0 = ivec2(frame.viewport.xy);
    const vec2 top = vec2(size0 - 1);
    ivec2 a = ivec2(clamp(floor((ndc_lo * 0.5 + 0.5) * frame.viewport.xy), vec2(0.0), top));
    ivec2 b = ivec2(clamp(floor((ndc_hi * 0.5 + 0.5) * frame.viewport.xy), vec2(0.0), top));
    uint k = 0u;
    ivec2 size = size0;
    while (k + 1u < push.levels && (b.x - a.x > 1 || b.y - a.y > 1)) {
        size = max(size / 2, ivec2(1));
        a = min(a / 2, size - 1);
        b = min(b / 2, size - 1);
        ++k;
    }
    float far = farther(fetch(k, a), fetch(k, b));
    far = farther(far, farther(fetch(k, ivec2(a.x, b.y)), fetch(k, ivec2(b.x, a.y))));
    const float tolerance = push.margin * max(abs(nearest), abs(far));
    const bool occluded = reverse ? far - nearest > tolerance : nearest - far > tolerance;
    finish(i, occluded ? kOccluded : kVisible, k, nearest, far);
}
