#version 460
// Depth prepass: no lighting. Writes the encoded world-space shading normal and the
// roughness that forward, GTAO and contact shadows read. Defines (default 0):
//   ALPHA_MASK=1       MASK materials: alpha test (base colour alpha only) before any other
//                      texture read; its discard makes the depth test late, so this
//                      pipeline is drawn after the opaque one, which keeps early-Z.
//   ALPHA_MASK=2       masked_split=off: one pipeline for all geometry, testing MASK
//                      materials only; the discard in it costs every draw its early-Z.
//   COUNT_FRAGMENTS=1  count the fragments that ran (common/count.glsl).
//   SURFACE_ID=1       also write the surface that won the depth test (attachment 2, u32).
//   ALPHA_TO_COVERAGE, COUNT_DISCARDS: see common/alpha_test.glsl (with ALPHA_MASK only).
//   PIXEL_HISTORY=1    the pixel history replay: records each fragment (common/pixel_history.glsl).
#extension GL_GOOGLE_include_directive : require

#ifndef ALPHA_MASK
#define ALPHA_MASK 0
#endif
#ifndef SURFACE_ID
#define SURFACE_ID 0
#endif

#include "common/alpha_test.glsl"
#include "common/count.glsl"
#include "common/pixel_history.glsl"
#include "common/surface.glsl"

#if COUNT_FRAGMENTS && ALPHA_MASK == 0
layout(early_fragment_tests) in;
#endif

layout(location = 0) in vec3 in_world_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_uv0;
layout(location = 3) in vec4 in_tangent;

layout(location = 0) out vec4 out_normal;
#if PIXEL_HISTORY  // the replay's one attachment is a stand-in for output 0: this is recorded
float out_roughness;
#else
layout(location = 1) out float out_roughness;
#endif
#if SURFACE_ID
layout(location = 4) flat in uint in_surface_base;
layout(location = 2) out uint out_surface;
#endif

void main() {
    count_fragment();
    float coverage = 1.0;  // output 0's alpha: the sample mask with alpha-to-coverage
#if ALPHA_MASK
    bool tested = ALPHA_MASK == 1 || (material.flags & kMaterialAlphaMask) != 0u;
    float alpha = texture(base_color_texture, in_uv0).a * material.base_color_factor.a;
    count_invoked();
#if ALPHA_TO_COVERAGE
    float sharpened = coverage_alpha(alpha, alpha_cutoff());  // outside the branch: fwidth
    if (tested) coverage = sharpened;
#else
    if (tested && alpha < alpha_cutoff()) {
        count_discarded();
        count_discarded_fragment();
        history_record(alpha, alpha_cutoff(), kHistoryAlphaTested | kHistoryDiscarded, vec4(0.0));
        discard;
    }
#endif
#endif
    out_normal = vec4(encode_normal(shading_normal(vertex_normal(in_normal), in_tangent, in_uv0)),
                      coverage);
    out_roughness = material_roughness(in_uv0);
#if ALPHA_MASK
    history_record(alpha, alpha_cutoff(), tested ? kHistoryAlphaTested : 0u, out_normal);
#else
    history_record(1.0, 0.0, 0u, out_normal);
#endif
#if SURFACE_ID
    out_surface = in_surface_base + uint(gl_PrimitiveID) + 1u;
#endif
}
