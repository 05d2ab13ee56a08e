#version 460
// Procedural sky: runs only where the scene depth is still "far" (the depth test against
// the prepass / forward depth rejects every covered pixel before this shader).
#extension GL_GOOGLE_include_directive : require

#include "common/sky.glsl"

layout(location = 0) in vec2 in_ndc;
layout(location = 0) out vec4 out_color;

void main() {
    // A point on the near plane: well conditioned for either depth convention.
    vec4 p = frame.inverse_view_projection *
             vec4(in_ndc, frame_has(kFrameReverseZ) ? 1.0 : 0.0, 1.0);
    vec3 dir = normalize(p.xyz / p.w - frame.camera_position.xyz);
    out_color = vec4(sky_radiance(dir), 1.0);
}
