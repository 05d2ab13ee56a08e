#version 460
// Shader depth resolve (msaa > 1 where the device has no MAX / MIN depth resolve mode, as
// lavapipe): the single-sample depth keeps the nearest of the pixel's samples, the largest
// with reverse-Z and the smallest otherwise, so GTAO, contact shadows and the covered-pixel
// count see the frontmost surface, not an average of two.
#extension GL_GOOGLE_include_directive : require

#include "common/frame.glsl"

layout(location = 0) in vec2 in_ndc;  // fullscreen.vert's; declared so the interfaces match
layout(set = 1, binding = 0) uniform sampler2DMS msaa_depth;
layout(push_constant) uniform Push {
    int samples;
} push;

void main() {
    const ivec2 p = ivec2(gl_FragCoord.xy);
    const bool reverse_z = frame_has(kFrameReverseZ);
    float nearest = texelFetch(msaa_depth, p, 0).r;
    for (int i = 1; i < push.samples; ++i) {
        const float d = texelFetch(msaa_depth, p, i).r;
        nearest = reverse_z ? max(nearest, d) : min(nearest, d);
    }
    gl_FragDepth = nearest;
}
