#version 460
// zfight's depth bound: the stored depth moved push.steps + 1 representable steps towards
// far (ULPs for D32_SFLOAT, unorm steps for D24 / D16; the extra step absorbs the device's
// rounding on store). The zfight pass tests closer-or-equal against it, so fragments more
// than zfight_steps behind the winner never run its shader; it still measures every gap
// against the stored depth itself. PER_SAMPLE=1 (msaa > 1): a multisampled bound, one
// invocation per sample (gl_SampleID turns sample shading on), each from its own stored sample.
#extension GL_GOOGLE_include_directive : require

#include "common/frame.glsl"

#ifndef PER_SAMPLE
#define PER_SAMPLE 0
#endif

layout(location = 0) in vec2 in_ndc;  // fullscreen.vert's; declared so the interfaces match
#if PER_SAMPLE
layout(set = 1, binding = 0) uniform sampler2DMS stored_depth;
#define STORED_SAMPLE gl_SampleID
#else
layout(set = 1, binding = 0) uniform sampler2D stored_depth;
#define STORED_SAMPLE 0  // the level
#endif
layout(push_constant) uniform Push {
    uint steps;
    uint depth_bits;  // 32: float, 24 / 16: unorm
}
push;

void main() {
    const float d = texelFetch(stored_depth, ivec2(gl_FragCoord.xy), STORED_SAMPLE).r;
    const bool reverse_z = frame_has(kFrameReverseZ);  // far is 0, the smaller float
    const uint n = push.steps + 1u;
    if (push.depth_bits == 32u) {
        const uint bits = floatBitsToUint(d);
        gl_FragDepth = reverse_z ? uintBitsToFloat(bits - min(bits, n))
                                 : min(uintBitsToFloat(bits + n), 1.0);
        return;
    }
    const float step = 1.0 / (push.depth_bits == 24u ? 16777215.0 : 65535.0);
    gl_FragDepth = clamp(d + (reverse_z ? -1.0 : 1.0) * float(n) * step, 0.0, 1.0);
}
