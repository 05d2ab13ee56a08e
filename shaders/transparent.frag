#version 460
// Transparent and decals passes: surfaces lit like forward without prepass inputs (they are
// not in the prepass), with their own normals. Screen-space AO and contact shadows apply
// too: the atrium's BLEND materials and every coplanar overlay lie on the opaque surface
// those images describe. Defines: COUNT_FRAGMENTS, PIXEL_HISTORY (common/pixel_history.glsl)
// (default 0); ALPHA_MODE (default 2):
//   0 OPAQUE  alpha written as 1 (no blending)
//   1 MASK    discard below the cutoff, then alpha 1 (no depth writes, so early tests hold)
//   2 BLEND   alpha for SRC_ALPHA / ONE_MINUS_SRC_ALPHA blending into the HDR target
#extension GL_GOOGLE_include_directive : require

#include "common/count.glsl"
#include "common/lighting.glsl"
#include "common/pixel_history.glsl"

#ifndef ALPHA_MODE
#define ALPHA_MODE 2
#endif

// No pipeline of this shader writes depth: testing early is the same test, and only
// fragments that pass it run (and are counted).
layout(early_fragment_tests) in;

layout(location = 0) in vec3 in_world_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_uv0;
layout(location = 3) in vec4 in_tangent;

layout(location = 0) out vec4 out_color;

void main() {
    count_fragment();
    vec4 base = texture(base_color_texture, texture_uv(kTextureBaseColor, in_uv0)) * material.base_color_factor;
#if ALPHA_MODE == 1
    const float alpha = mask_alpha(in_uv0, base.a);
    if (alpha < alpha_cutoff()) {
        count_discarded_fragment();
        history_record(alpha, alpha_cutoff(), kHistoryAlphaTested | kHistoryDiscarded,
                       vec4(0.0));
        discard;
    }
#endif
    vec3 n_vertex = vertex_normal(in_normal);
    Surface s = material_surface(base, in_uv0);
    s.n = shading_normal(n_vertex, in_tangent, in_uv0);
    s.roughness = material_roughness(in_uv0);
    s.occlusion *= screen_ao();
    float sun = sun_shadow(in_world_position, facing(n_vertex)) * screen_contact_shadow();
    out_color = vec4(shade(s, in_world_position, sun), ALPHA_MODE == 2 ? base.a : 1.0);
#if ALPHA_MODE == 1
    history_record(alpha, alpha_cutoff(), kHistoryAlphaTested | kHistoryColor, out_color);
#else
    history_record(base.a, 0.0, kHistoryColor, out_color);
#endif
}
