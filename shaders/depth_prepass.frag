#version 460
// Depth prepass: no lighting. Defines (default 0 unless said):
//   GBUFFER=1 (default) prepass_mode=gbuffer: writes the encoded world-space shading normal
//                      (attachment 0) and the roughness (1) that forward, GTAO and contact
//                      shadows read. GBUFFER=0, prepass_mode=depth: writes no colour; this
//                      shader then exists only for the alpha test (masked geometry) or a
//                      diagnostic (counting, surface_id, pixel history): plain opaque
//                      geometry has no fragment stage at all (DepthPrepass).
//   ALPHA_MASK=1       MASK materials: alpha test (base colour alpha only) before any other
//                      texture read; its discard makes the depth test late, so this
//                      pipeline is drawn after the opaque one, which keeps early-Z.
//   ALPHA_MASK=2       masked_split=off: one pipeline for all geometry, testing MASK
//                      materials only; the discard in it costs every draw its early-Z.
//   COUNT_FRAGMENTS=1  count the fragments that ran (common/count.glsl).
//   SURFACE_ID=1       also write the surface that won the depth test (u32): attachment 2
//                      with GBUFFER=1, SURFACE_LOCATION (0, or 1 after the coverage slot)
//                      with GBUFFER=0.
//   COVERAGE_SLOT=1    GBUFFER=0 with alpha_to_coverage: colour slot 0 has no image; every
//                      variant writes output 0 (an unwritten attachment draws a validation
//                      warning), the ones without the alpha test a coverage of 1.
//   ALPHA_MIP=1        alpha_mip=on: also write, at ALPHA_MIP_LOCATION (after surface_id),
//                      the mip level the alpha test sampled, textureQueryLod().x (the level
//                      accessed; 0 with alpha_level0), on MASK surfaces, and -1 ("none")
//                      on every other surface.
//   ALPHA_TO_COVERAGE, COUNT_DISCARDS: see common/alpha_test.glsl (with ALPHA_MASK only).
//                      With GBUFFER=0 the sharpened alpha goes to output 0, whose attachment
//                      slot has no image: alpha to coverage reads output 0 whatever is bound.
//   PIXEL_HISTORY=1    the pixel history replay: records each fragment (common/pixel_history.glsl).
//   LIGHT_SLOT=1       render_path=subpass (seed 002's subpass 0): output 0 is the light, the
//                      "emissive" output seed 002 gives the G-buffer pass: none here (forward
//                      adds emission when it lights the same samples under EQUAL), and its
//                      alpha is the alpha-to-coverage input. Normal and roughness move to 1, 2.
//                      (A write mask of 0 would need independentBlend, which lavapipe lacks.)
#extension GL_GOOGLE_include_directive : require

#ifndef GBUFFER
#define GBUFFER 1
#endif
#ifndef ALPHA_MASK
#define ALPHA_MASK 0
#endif
#ifndef SURFACE_ID
#define SURFACE_ID 0
#endif
#ifndef SURFACE_LOCATION
#define SURFACE_LOCATION 0
#endif
#ifndef LIGHT_SLOT
#define LIGHT_SLOT 0
#endif
#ifndef ALPHA_MIP
#define ALPHA_MIP 0
#endif
#ifndef COVERAGE_SLOT
#define COVERAGE_SLOT 0
#endif
#ifndef ALPHA_MIP_LOCATION
#define ALPHA_MIP_LOCATION 3
#endif

#include "common/alpha_test.glsl"
#include "common/count.glsl"
#include "common/pixel_history.glsl"
#include "common/surface.glsl"

#if COUNT_FRAGMENTS && ALPHA_MASK == 0
layout(early_fragment_tests) in;
#endif

#if GBUFFER
layout(location = 0) in vec3 in_world_position;
layout(location = 1) in vec3 in_normal;
layout(location = 3) in vec4 in_tangent;
#endif
#if GBUFFER || ALPHA_MASK
layout(location = 2) in vec2 in_uv0;
#endif

// Output 0: the normal (G-buffer), or with GBUFFER=0 the coverage alpha / the replay's
// stand-in attachment where one of those needs it. LIGHT_SLOT=1: the light is output 0 and
// takes the coverage alpha; the normal (G-buffer only) moves to 1.
#if LIGHT_SLOT
layout(location = 0) out vec4 out_light;
#define HAS_OUTPUT0 GBUFFER
#else
#define HAS_OUTPUT0 \
    (GBUFFER || PIXEL_HISTORY || (ALPHA_MASK && ALPHA_TO_COVERAGE) || COVERAGE_SLOT)
#endif
#if HAS_OUTPUT0
layout(location = LIGHT_SLOT) out vec4 out_normal;
#endif
#if GBUFFER && !PIXEL_HISTORY
layout(location = LIGHT_SLOT + 1) out float out_roughness;
#else  // the replay's one attachment is a stand-in for output 0: this is recorded
float out_roughness;
#endif
#if ALPHA_MIP
layout(location = ALPHA_MIP_LOCATION) out float out_alpha_mip;
#endif
#if SURFACE_ID
layout(location = 4) flat in uint in_surface_base;
#if GBUFFER
layout(location = 2) out uint out_surface;
#else
layout(location = SURFACE_LOCATION) out uint out_surface;
#endif
#endif

void main() {
    count_fragment();
    float coverage = 1.0;  // output 0's alpha: the sample mask with alpha-to-coverage
#if ALPHA_MASK
    bool tested = ALPHA_MASK == 1 || (material.flags & kMaterialAlphaMask) != 0u;
    vec2 base_uv = texture_uv(kTextureBaseColor, in_uv0);
    float alpha =
        mask_alpha(in_uv0, texture(base_color_texture, base_uv).a * material.base_color_factor.a);
#if ALPHA_MIP
    // Before the discard, while the whole quad runs (implicit derivatives).
    float sampled_level = alpha_level0() ? 0.0 : textureQueryLod(base_color_texture, base_uv).x;
#endif
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
#if GBUFFER
    out_normal = vec4(encode_normal(shading_normal(vertex_normal(in_normal), in_tangent, in_uv0)),
                      coverage);
    out_roughness = material_roughness(in_uv0);
#elif HAS_OUTPUT0
    out_normal = vec4(0.0, 0.0, 0.0, coverage);  // no colour: only the alpha is used
#endif
#if HAS_OUTPUT0
    vec4 recorded = out_normal;
#else
    vec4 recorded = vec4(0.0);
#endif
#if ALPHA_MASK
    history_record(alpha, alpha_cutoff(), tested ? kHistoryAlphaTested : 0u, recorded);
#else
    history_record(1.0, 0.0, 0u, recorded);
#endif
#if SURFACE_ID
    out_surface = in_surface_base + uint(gl_PrimitiveID) + 1u;
#endif
#if ALPHA_MIP && ALPHA_MASK
    out_alpha_mip = tested ? sampled_level : -1.0;
#elif ALPHA_MIP
    out_alpha_mip = -1.0;
#endif
#if LIGHT_SLOT
    out_light = vec4(0.0, 0.0, 0.0, coverage);
#endif
}
