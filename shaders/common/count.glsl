// Exact per-pixel counts of fragments that ran a shader (count_fragments=on), set 3: binding 0
// every fragment that ran (count_fragment() first thing in main), binding 1 those the alpha
// test discarded (count_discarded_fragment() just before the discard). Lavapipe's
// fragment-invocation statistic counts 4x4 blocks before the depth test (DESIGN decision 2),
// so the shaders count themselves. A counting shader without discard declares
// layout(early_fragment_tests), so only fragments that passed the depth test run; one with
// discard tests depth late, so every fragment it rasterized runs, and counts.
#ifndef DS_COUNT_GLSL
#define DS_COUNT_GLSL

#ifndef COUNT_FRAGMENTS
#define COUNT_FRAGMENTS 0
#endif

#if COUNT_FRAGMENTS
layout(set = 3, binding = 0, r32ui) uniform uimage2D fragment_counts;
layout(set = 3, binding = 1, r32ui) uniform uimage2D discarded_counts;

void count_fragment() {
    imageAtomicAdd(fragment_counts, ivec2(gl_FragCoord.xy), 1u);
}
void count_discarded_fragment() {
    imageAtomicAdd(discarded_counts, ivec2(gl_FragCoord.xy), 1u);
}
#else
void count_fragment() {}
void count_discarded_fragment() {}
#endif

#endif
