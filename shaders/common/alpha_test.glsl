// The MASK alpha test, shared by the depth prepass and forward. Defines (default 0):
//   ALPHA_TO_COVERAGE=1  alpha_to_coverage=on at msaa > 1: no discard; the pipeline turns
//                        colour output 0's alpha into the sample mask (coverage_alpha()).
//   COUNT_DISCARDS=1     count_discards=on (prepass MASK pipeline): fragments that ran the
//                        test and those it discarded, atomics in a storage buffer at set 2.
#ifndef DS_ALPHA_TEST_GLSL
#define DS_ALPHA_TEST_GLSL

#include "bindings.glsl"

#ifndef ALPHA_TO_COVERAGE
#define ALPHA_TO_COVERAGE 0
#endif
#ifndef COUNT_DISCARDS
#define COUNT_DISCARDS 0
#endif

// Alpha for alpha-to-coverage: the cutoff maps to 0.5 and the ramp is sharpened to about one
// pixel (fwidth), so the cutoff still decides where the edge lies and coverage only
// antialiases it; raw alpha would dither a whole gradient and ignore the cutoff.
float coverage_alpha(float alpha, float cutoff) {
    return clamp((alpha - cutoff) / max(fwidth(alpha), 1e-4) + 0.5, 0.0, 1.0);
}

#if COUNT_DISCARDS
layout(set = 2, binding = 0, std430) buffer DiscardCounts {
    uint invoked;
    uint discarded;
}
discard_counts;

void count_invoked() {
    atomicAdd(discard_counts.invoked, 1u);
}
void count_discarded() {
    atomicAdd(discard_counts.discarded, 1u);
}
#else
void count_invoked() {}
void count_discarded() {}
#endif

#endif
