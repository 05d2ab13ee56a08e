#version 460
// Transparent pass: BLEND materials lit like forward (without prepass inputs: they are not
// in the prepass), output alpha for SRC_ALPHA / ONE_MINUS_SRC_ALPHA blending into the HDR
// target. Screen-space AO and contact shadows apply too: the atrium's BLEND materials are
// decals lying on the opaque surface those images describe. No discard, so the counting
// variant keeps early tests. Defines: COUNT_FRAGMENTS (default 0).
#extension GL_GOOGLE_include_directive : require

#include "common/count.glsl"
#include "common/lighting.glsl"

#if COUNT_FRAGMENTS
layout(early_fragment_tests) in;
#endif

layout(location = 0) in vec3 in_world_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_uv0;
layout(location = 3) in vec4 in_tangent;

layout(location = 0) out vec4 out_color;

void main() {
    vec4 base = texture(base_color_texture, in_uv0) * material.base_color_factor;
    count_fragment();
    vec3 n_vertex = vertex_normal(in_normal);
    Surface s = material_surface(base, in_uv0);
    s.n = shading_normal(n_vertex, in_tangent, in_uv0);
    s.roughness = material_roughness(in_uv0);
    s.occlusion *= screen_ao();
    float sun = sun_shadow(in_world_position, facing(n_vertex)) * screen_contact_shadow();
    out_color = vec4(shade(s, in_world_position, sun), base.a);
}
