#version 460
// One triangle covering the viewport, at the far depth of the frame's convention (0 with
// reverse-Z, else 1): the sky tests it against the scene depth; tonemap has no depth.
#extension GL_GOOGLE_include_directive : require

#include "common/frame.glsl"

layout(location = 0) out vec2 out_ndc;

void main() {
    vec2 p = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);  // (0,0) (2,0) (0,2)
    out_ndc = p * 2.0 - 1.0;
    gl_Position = vec4(out_ndc, frame_has(kFrameReverseZ) ? 0.0 : 1.0, 1.0);
}
