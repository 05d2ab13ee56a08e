#version 460
// Shadow map fragment shader. Opaque geometry normally uses a pipeline without one; this
// runs for MASK materials (ALPHA_MASK=1, the default: the cut-out parts of leaves cast no
// shadow) and, with COUNT_FRAGMENTS=1 (common/count.glsl), for opaque ones too
// (ALPHA_MASK=0), which then only count, with early fragment tests as the depth-only
// pipeline has.
#extension GL_GOOGLE_include_directive : require

#ifndef ALPHA_MASK
#define ALPHA_MASK 1
#endif

#include "common/bindings.glsl"
#include "common/count.glsl"

#if !ALPHA_MASK
layout(early_fragment_tests) in;
#endif

layout(location = 0) in vec2 in_uv0;

void main() {
    count_fragment();
#if ALPHA_MASK
    float sampled = texture(base_color_texture, texture_uv(kTextureBaseColor, in_uv0)).a;
    float alpha = mask_alpha(in_uv0, sampled * material.base_color_factor.a);
    if (alpha < alpha_cutoff()) {
        count_discarded_fragment();
        discard;
    }
#endif
}
