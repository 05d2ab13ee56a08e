#version 460
// Forward pass vertex shader. gl_Position is invariant and computed as
// view_projection * (model * position): the prepass (next issue) must use the same
// expression so an EQUAL depth test matches bit for bit (seed 000).
#extension GL_GOOGLE_include_directive : require

#include "common/bindings.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_uv0;
layout(location = 3) in vec4 in_tangent;

layout(location = 0) out vec3 out_world_position;
layout(location = 1) out vec3 out_normal;
layout(location = 2) out vec2 out_uv0;
layout(location = 3) out vec4 out_tangent;

invariant gl_Position;

void main() {
    InstanceData instance = instances[gl_InstanceIndex];
    vec4 world = instance.model * vec4(in_position, 1.0);
    gl_Position = frame.view_projection * world;
    out_world_position = world.xyz;
    out_normal = mat3(instance.normal_matrix) * in_normal;
    out_tangent = vec4(mat3(instance.model) * in_tangent.xyz, in_tangent.w);
    out_uv0 = in_uv0;
}
