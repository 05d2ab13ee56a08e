// Exact per-pixel counts of fragments that ran a shader (count_fragments=on), set 3: binding 0
// every fragment that ran (count_fragment() first thing in main), binding 1 those the alpha
// test discarded (count_discarded_fragment() just before the discard), binding 3 with
// COUNT_QUADS=1 (devices with quad subgroup operations in fragment shaders) the 2x2 quads
// that ran, one texel per quad. Lavapipe's fragment-invocation statistic counts 4x4 blocks
// before the depth test (DESIGN decision 2), so the shaders count themselves. A counting
// shader without discard declares layout(early_fragment_tests), so only fragments that passed
// the depth test run; one with discard tests depth late, so every fragment it rasterized runs,
// and counts.
// COUNT_DRAWS=1 (count_draws=on, with COUNT_FRAGMENTS): binding 2 holds one counter per scene
// draw group, and count_fragment() also adds one to its draw's (the vertex shader passes the
// group on: common/count_draws.glsl). Without it the shaders are exactly as before.
#ifndef DS_COUNT_GLSL
#define DS_COUNT_GLSL

#ifndef COUNT_FRAGMENTS
#define COUNT_FRAGMENTS 0
#endif
#ifndef COUNT_QUADS
#define COUNT_QUADS 0
#endif

#ifndef COUNT_DRAWS
#define COUNT_DRAWS 0
#endif

#if COUNT_FRAGMENTS
layout(set = 3, binding = 0, r32ui) uniform uimage2D fragment_counts;
layout(set = 3, binding = 1, r32ui) uniform uimage2D discarded_counts;
#if COUNT_DRAWS
layout(set = 3, binding = 2, std430) buffer DrawCounts {
    uint draw_counts[];
};
layout(location = 5) flat in uint in_draw_group;
#endif

#if COUNT_QUADS
#extension GL_KHR_shader_subgroup_quad : require
layout(set = 3, binding = 3, r32ui) uniform uimage2D quad_counts;

// Called in uniform control flow, before any discard, so all four lanes of the quad (helpers
// included) take part: the lowest live lane counts the quad once. Helper lanes' stores do
// nothing, so a quad of helpers only is not counted: it shaded nothing.
void count_quad() {
    uint lane = gl_HelperInvocation ? 4u : (gl_SubgroupInvocationID & 3u);
    uint lowest = min(lane, subgroupQuadSwapHorizontal(lane));
    lowest = min(lowest, subgroupQuadSwapVertical(lowest));
    if (!gl_HelperInvocation && lane == lowest)
        imageAtomicAdd(quad_counts, ivec2(gl_FragCoord.xy) / 2, 1u);
}
#else
void count_quad() {}
#endif

void count_fragment() {
    count_quad();
    imageAtomicAdd(fragment_counts, ivec2(gl_FragCoord.xy), 1u);
#if COUNT_DRAWS
    atomicAdd(draw_counts[in_draw_group], 1u);
#endif
}
void count_discarded_fragment() {
    imageAtomicAdd(discarded_counts, ivec2(gl_FragCoord.xy), 1u);
}
#else
void count_fragment() {}
void count_discarded_fragment() {}
#endif

#endif
