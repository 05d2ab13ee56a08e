// A scene surface's normal and roughness, computed the same way by the depth prepass (which
// stores them) and by the forward pass without a prepass (which uses them at once), so
// prepass on and off light alike.
#ifndef DS_SURFACE_GLSL
#define DS_SURFACE_GLSL

#include "bindings.glsl"
#include "normal.glsl"

// Unit interpolated vertex normal (front side); a degenerate one becomes +Y, not NaN.
vec3 vertex_normal(vec3 interpolated) {
    float len2 = dot(interpolated, interpolated);
    return len2 > 1e-12 ? interpolated * inversesqrt(len2) : vec3(0.0, 1.0, 0.0);
}

// The geometric normal on the viewer's side: back faces of double-sided materials are lit
// as seen from their own side.
vec3 facing(vec3 n) {
    return gl_FrontFacing ? n : -n;
}

// Normal-mapped shading normal on the viewer's side. perturb_normal() guards degenerate
// tangents (missing, zero, parallel to n, NaN) by keeping the vertex normal.
vec3 shading_normal(vec3 n, vec4 tangent, vec2 uv) {
    if ((material.flags & kMaterialHasNormalMap) != 0u) {
        vec3 texel = texture(normal_texture, texture_uv(kTextureNormal, uv)).xyz;
        n = perturb_normal(n, tangent, texel, material.normal_scale);
    }
    return facing(n);
}

// Metallic-roughness texture G x factor (perceptual roughness).
float material_roughness(vec2 uv) {
    return clamp(texture(metallic_roughness_texture, texture_uv(kTextureMetallicRoughness, uv)).g * material.roughness_factor, 0.0, 1.0);
}

// [-1, 1] <-> [0, 1] per axis (A2B10G10R10_UNORM): a linear encoding, so an MSAA AVERAGE
// resolve averages directions correctly after decoding and renormalising (seed 000).
vec3 encode_normal(vec3 n) {
    return n * 0.5 + 0.5;
}
vec3 decode_normal(vec3 e) {
    vec3 n = e * 2.0 - 1.0;
    float len2 = dot(n, n);
    return len2 > 1e-12 ? n * inversesqrt(len2) : vec3(0.0, 1.0, 0.0);
}

#endif
