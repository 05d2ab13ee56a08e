#version 460
// HDR -> exposure -> ACES fit -> the _SRGB final image (the hardware encodes). One texel per
// pixel: the HDR image has the output's size.
#extension GL_GOOGLE_include_directive : require

#include "common/frame.glsl"
#include "common/tonemap.glsl"

layout(set = 1, binding = 0) uniform sampler2D hdr;

layout(location = 0) in vec2 in_ndc;
layout(location = 0) out vec4 out_color;

void main() {
    // gl_FragCoord picks the texel exactly; in_ndc only keeps the stage interface whole.
    vec3 radiance = texelFetch(hdr, ivec2(gl_FragCoord.xy), 0).rgb + 0.0 * in_ndc.x;
    out_color = vec4(tonemap(radiance, frame.depth_params.w), 1.0);
}
