#version 460
// Shadow map: scene geometry in the sun's orthographic clip space (fitted to the scene
// bounds on the CPU). Position and uv only; uv feeds the MASK pipeline's alpha test.
#extension GL_GOOGLE_include_directive : require

#include "common/bindings.glsl"
#include "common/count_draws.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 2) in vec2 in_uv0;

layout(location = 0) out vec2 out_uv0;

void main() {
    gl_Position = frame.sun_view_projection *
                  (instances[gl_InstanceIndex].model * vec4(in_position, 1.0));
    out_uv0 = in_uv0;
    PASS_DRAW_GROUP(instances[gl_InstanceIndex]);
}
