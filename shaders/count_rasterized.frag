#version 460
// count_fragments=on: a geometry pass's rasterized fragments (renderer/passes/rasterized_count.h).
// Its draws again with the depth test off and no attachments: every fragment they rasterize
// runs this, once per pixel a primitive covers (at msaa > 1 once per pixel, not per sample),
// whatever the depth test or a discard would have made of it.
// SHADOW_VERTEX=1: after shadow.vert (uv only), else the scene vertex shader. Its outputs
// are declared, unused, so the interfaces match.
layout(early_fragment_tests) in;

#ifndef SHADOW_VERTEX
#define SHADOW_VERTEX 0
#endif
#if SHADOW_VERTEX
layout(location = 0) in vec2 in_uv0;
#else
layout(location = 0) in vec3 in_world_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_uv0;
layout(location = 3) in vec4 in_tangent;
#endif

layout(set = 2, binding = 0, r32ui) uniform uimage2D rasterized_counts;

void main() {
    imageAtomicAdd(rasterized_counts, ivec2(gl_FragCoord.xy), 1u);
}
