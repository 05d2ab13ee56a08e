// Exact per-pixel counts of fragments that ran a shader (count_fragments=on), set 3.
// Lavapipe's fragment-invocation statistic counts 4x4 blocks before the depth test
// (DESIGN decision 2), so the shaders count themselves. A counting shader without discard
// declares layout(early_fragment_tests) so the depth test runs before it and only survivors
// count; one with discard counts after its discard, and its depth test runs late (a fragment
// that survives the alpha test but then fails the depth test is counted too).
#ifndef DS_COUNT_GLSL
#define DS_COUNT_GLSL

#ifndef COUNT_FRAGMENTS
#define COUNT_FRAGMENTS 0
#endif

#if COUNT_FRAGMENTS
layout(set = 3, binding = 0, r32ui) uniform uimage2D fragment_counts;

void count_fragment() {
    imageAtomicAdd(fragment_counts, ivec2(gl_FragCoord.xy), 1u);
}
#else
void count_fragment() {}
#endif

#endif
