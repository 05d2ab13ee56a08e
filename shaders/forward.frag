#version 460
// Forward pass: metallic-roughness PBR lit by the sun (PCF shadow map, contact shadows) and a
// hemispherical ambient (material AO x GTAO), into the HDR target. Defines (default 0):
//   PREPASS=1          normal and roughness come from the prepass images. With EQUAL no
//                      variant has a discard: the test already keeps only what the masked
//                      prepass kept, so every forward pipeline keeps early-Z.
//   ALPHA_MASK=1       MASK materials without the prepass, or with depth_compare=
//                      greater_or_equal (which cut-out parts would pass): alpha test with
//                      discard, in its own pipeline drawn after opaque.
//   COUNT_FRAGMENTS=1  count the fragments that ran (common/count.glsl).
//   ALPHA_TO_COVERAGE=1  with ALPHA_MASK: coverage instead of discard (common/alpha_test.glsl).
//   PIXEL_HISTORY=1    the pixel history replay: records each fragment (common/pixel_history.glsl).
//   SUBPASS_INPUTS=N   render_path=subpass (seed 002's subpass 1): normal and roughness are
//                      the prepass's input attachments (set 4), N samples each, averaged as
//                      the dynamic path's AVERAGE resolve does.
#extension GL_GOOGLE_include_directive : require

#ifndef PREPASS
#define PREPASS 0
#endif
#ifndef ALPHA_MASK
#define ALPHA_MASK 0
#endif
#ifndef SUBPASS_INPUTS
#define SUBPASS_INPUTS 0
#endif

#include "common/alpha_test.glsl"
#include "common/count.glsl"
#include "common/lighting.glsl"
#include "common/pixel_history.glsl"

#if COUNT_FRAGMENTS && ALPHA_MASK == 0
layout(early_fragment_tests) in;
#endif

layout(location = 0) in vec3 in_world_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_uv0;
layout(location = 3) in vec4 in_tangent;

layout(location = 0) out vec4 out_color;

#if SUBPASS_INPUTS > 1
layout(input_attachment_index = 0, set = 4, binding = 0) uniform subpassInputMS gbuffer_normals;
layout(input_attachment_index = 1, set = 4, binding = 1) uniform subpassInputMS gbuffer_roughness;
#elif SUBPASS_INPUTS == 1
layout(input_attachment_index = 0, set = 4, binding = 0) uniform subpassInput gbuffer_normals;
layout(input_attachment_index = 1, set = 4, binding = 1) uniform subpassInput gbuffer_roughness;
#endif

#if SUBPASS_INPUTS
// The pixel's encoded normal (xyz) and roughness (w), from tile memory.
vec4 load_gbuffer() {
#if SUBPASS_INPUTS > 1
    vec4 sum = vec4(0.0);
    for (int i = 0; i < SUBPASS_INPUTS; ++i)
        sum += vec4(subpassLoad(gbuffer_normals, i).xyz, subpassLoad(gbuffer_roughness, i).r);
    return sum / float(SUBPASS_INPUTS);
#else
    return vec4(subpassLoad(gbuffer_normals).xyz, subpassLoad(gbuffer_roughness).r);
#endif
}
#endif

void main() {
    count_fragment();
    vec4 base = texture(base_color_texture, texture_uv(kTextureBaseColor, in_uv0)) * material.base_color_factor;
    float coverage = 1.0;  // output alpha: the sample mask with alpha-to-coverage
#if ALPHA_MASK
    const float alpha = mask_alpha(in_uv0, base.a);
#endif
#if ALPHA_MASK && ALPHA_TO_COVERAGE
    coverage = coverage_alpha(alpha, alpha_cutoff());
#elif ALPHA_MASK
    if (alpha < alpha_cutoff()) {
        count_discarded_fragment();
        history_record(alpha, alpha_cutoff(), kHistoryAlphaTested | kHistoryDiscarded,
                       vec4(0.0));
        discard;
    }
#endif
    vec3 n_vertex = vertex_normal(in_normal);
    Surface s = material_surface(base, in_uv0);
#if SUBPASS_INPUTS
    vec4 gbuffer = load_gbuffer();
    s.n = decode_normal(gbuffer.xyz);
    s.roughness = gbuffer.w;
#elif PREPASS
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    s.n = decode_normal(texelFetch(prepass_normals, pixel, 0).xyz);
    s.roughness = texelFetch(prepass_roughness, pixel, 0).r;
#else
    s.n = shading_normal(n_vertex, in_tangent, in_uv0);
    s.roughness = material_roughness(in_uv0);
#endif
    s.occlusion *= screen_ao();
    float sun = sun_shadow(in_world_position, facing(n_vertex)) * screen_contact_shadow();
    out_color = vec4(shade(s, in_world_position, sun), coverage);
#if ALPHA_MASK
    history_record(alpha, alpha_cutoff(), kHistoryAlphaTested | kHistoryColor, out_color);
#else
    history_record(base.a, 0.0, kHistoryColor, out_color);
#endif
}
