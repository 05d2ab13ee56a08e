#version 460
// Forward pass: PBR-lite shading, sun + hemispherical ambient, exposure + ACES, written to an
// _SRGB target. Defines: ALPHA_MASK (discard below the cutoff; its own pipeline so opaque
// geometry keeps early-Z), ALPHA_BLEND (output alpha for blending). Neither: opaque.
#extension GL_GOOGLE_include_directive : require

#include "common/bindings.glsl"
#include "common/brdf.glsl"
#include "common/normal.glsl"
#include "common/tonemap.glsl"

layout(location = 0) in vec3 in_world_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_uv0;
layout(location = 3) in vec4 in_tangent;

layout(location = 0) out vec4 out_color;

vec3 shading_normal() {
    vec3 n = in_normal;
    float n_len2 = dot(n, n);
    n = n_len2 > 1e-12 ? n * inversesqrt(n_len2) : vec3(0.0, 1.0, 0.0);
    if ((material.flags & kMaterialHasNormalMap) != 0u) {
        vec3 texel = texture(normal_texture, in_uv0).xyz;
        n = perturb_normal(n, in_tangent, texel, material.normal_scale);
    }
    // Back faces (double-sided materials) are lit as seen from their own side.
    return gl_FrontFacing ? n : -n;
}

void main() {
    vec4 base = texture(base_color_texture, in_uv0) * material.base_color_factor;
#ifdef ALPHA_MASK
    if (base.a < material.alpha_cutoff) discard;
#endif
    vec3 n = shading_normal();
    vec3 v = normalize(frame.camera_position.xyz - in_world_position);
    vec4 mr = texture(metallic_roughness_texture, in_uv0);
    float metallic = clamp(mr.b * material.metallic_factor, 0.0, 1.0);
    float roughness = clamp(mr.g * material.roughness_factor, 0.0, 1.0);
    float ao = 1.0 + material.occlusion_strength * (texture(occlusion_texture, in_uv0).r - 1.0);
    SurfaceBrdf s = surface_brdf(base.rgb, metallic, roughness);

    vec3 color = shade_direct(s, n, v, frame.sun_direction.xyz, frame.sun_radiance.rgb);

    // Hemispherical ambient: diffuse by the normal, specular by the reflection vector.
    float n_dot_v = max(abs(dot(n, v)), 1e-4);
    vec3 r = reflect(-v, n);
    vec3 diffuse_ambient = mix(frame.ground_ambient.rgb, frame.sky_ambient.rgb, n.y * 0.5 + 0.5);
    vec3 specular_ambient = mix(frame.ground_ambient.rgb, frame.sky_ambient.rgb, r.y * 0.5 + 0.5);
    color += ao * (diffuse_ambient * s.diffuse_color +
                   specular_ambient * env_brdf_approx(s.f0, roughness, n_dot_v));
    color += texture(emissive_texture, in_uv0).rgb * material.emissive_factor.rgb;

    color = tonemap(color, frame.exposure.x);
#ifdef ALPHA_BLEND
    out_color = vec4(color, base.a);
#else
    out_color = vec4(color, 1.0);
#endif
}
