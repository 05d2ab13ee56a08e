#version 460
// Shadow map, MASK materials: the cut-out parts of leaves cast no shadow. Opaque geometry
// uses a pipeline without a fragment shader.
#extension GL_GOOGLE_include_directive : require

#include "common/bindings.glsl"

layout(location = 0) in vec2 in_uv0;

void main() {
    float alpha = texture(base_color_texture, in_uv0).a * material.base_color_factor.a;
    if (alpha < alpha_cutoff()) discard;
}
