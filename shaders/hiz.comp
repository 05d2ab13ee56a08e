#version 460
// hiz: one level of the Hi-Z pyramid (renderer/passes/hiz.h), each texel the farthest depth of
// what it covers (reverse-Z: the minimum, forward-Z: the maximum), so a box nearer than that
// value may be visible there and one farther cannot be. Values are copied, never computed.
//   HIZ_MODE 0: level 0 from the single-sample prepass depth (a copy);
//   HIZ_MODE 1: level 0 from the multisampled depth, the farthest of the pixel's samples;
//   HIZ_MODE 2: level k+1 from level k. A child (x, y) covers parent texels 2x..2x+1 and
//     2y..2y+1, clamped to the parent; the last column (row) of the child also takes the
//     parent's last column (row) when the parent's width (height) is odd: 3 wide there. So
//     every parent texel has exactly one child: min(p / 2, child size - 1).
#extension GL_GOOGLE_include_directive : require

#include "common/frame.glsl"

#ifndef HIZ_MODE
#define HIZ_MODE 2
#endif

layout(local_size_x = 8, local_size_y = 8) in;

#if HIZ_MODE == 1
layout(set = 1, binding = 0) uniform sampler2DMS source;
#else
layout(set = 1, binding = 0) uniform sampler2D source;
#endif
layout(set = 1, binding = 1, r32f) uniform writeonly image2D level;

layout(push_constant) uniform Push {
    int samples;  // HIZ_MODE 1: the source's sample count
}
push;

float farther(float a, float b) {
    return frame.depth_params.z > 0.5 ? min(a, b) : max(a, b);
}

void main() {
    const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    const ivec2 size = imageSize(level);
    if (any(greaterThanEqual(p, size))) return;
#if HIZ_MODE == 0
    const float d = texelFetch(source, p, 0).r;
#elif HIZ_MODE == 1
    float d = texelFetch(source, p, 0).r;
    for (int s = 1; s < push.samples; ++s) d = farther(d, texelFetch(source, p, s).r);
#else
    const ivec2 parent = textureSize(source, 0);
    const ivec2 first = 2 * p;
    ivec2 last = min(first + 1, parent - 1);
    if (p.x == size.x - 1) last.x = parent.x - 1;
    if (p.y == size.y - 1) last.y = parent.y - 1;
    float d = texelFetch(source, first, 0).r;
    for (int y = first.y; y <= last.y; ++y)
        for (int x = first.x; x <= last.x; ++x) d = farther(d, texelFetch(source, ivec2(x, y), 0).r);
#endif
    imageStore(level, p, vec4(d, 0.0, 0.0, 0.0));
}
