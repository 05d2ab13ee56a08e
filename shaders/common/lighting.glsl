// Set 2 of the passes that light scene surfaces (forward, transparent): the sun's shadow
// map and the screen-space inputs, plus the lighting model they share. Must match
// renderer/passes/scene_draw.cpp (create_lighting_set_layout). Bindings a pass has no image
// for hold 1x1 fallbacks (white; a shadow map that lights everything).
#ifndef DS_LIGHTING_GLSL
#define DS_LIGHTING_GLSL

#include "bindings.glsl"
#include "brdf.glsl"
#include "surface.glsl"

layout(set = 2, binding = 0) uniform sampler2DShadow shadow_map;  // compare LESS_OR_EQUAL
layout(set = 2, binding = 1) uniform sampler2D prepass_normals;    // n * 0.5 + 0.5
layout(set = 2, binding = 2) uniform sampler2D prepass_roughness;  // R
layout(set = 2, binding = 3) uniform sampler2D ao_texture;         // R, 1 = unoccluded
layout(set = 2, binding = 4) uniform sampler2D contact_texture;    // R, 1 = lit

// PCF over a 3x3 grid of (bilinear, where the format allows) compare taps. The lookup
// point moves 1.5 shadow texels along the geometric normal, and the reference depth half a
// texel towards the sun, against acne on surfaces at grazing angles to the light.
float sun_shadow(vec3 world, vec3 geometric) {
    if (!frame_has(kFrameShadows)) return 1.0;
    mat4 m = frame.sun_view_projection;
    vec2 size = vec2(textureSize(shadow_map, 0));
    // Rows of an orthographic projection: 2 / width in x, 1 / depth range in z.
    float texel = 2.0 / (length(vec3(m[0][0], m[1][0], m[2][0])) * size.x);
    float z_per_metre = length(vec3(m[0][2], m[1][2], m[2][2]));
    vec4 c = m * vec4(world + geometric * (1.5 * texel), 1.0);
    vec2 uv = c.xy * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))) || c.z > 1.0) return 1.0;
    float ref = c.z - 0.5 * texel * z_per_metre;
    float lit = 0.0;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x)
            lit += texture(shadow_map, vec3(uv + vec2(x, y) / size, ref));
    return lit / 9.0;
}

// Screen-space inputs at this fragment (full-resolution uv: the images may be smaller).
float screen_ao() {
    if (!frame_has(kFrameAO)) return 1.0;
    return texture(ao_texture, gl_FragCoord.xy * frame.viewport.zw).r;
}
float screen_contact_shadow() {
    if (!frame_has(kFrameContactShadows)) return 1.0;
    return texture(contact_texture, gl_FragCoord.xy * frame.viewport.zw).r;
}

struct Surface {
    vec3 base_color;
    float metallic;
    float roughness;  // perceptual
    vec3 n;           // shading normal, unit
    float occlusion;  // material AO x screen-space AO
    vec3 emissive;
};

// Sun (GGX specular, Smith visibility, Schlick Fresnel + Lambert) times its shadowing, plus
// a hemispherical ambient: diffuse by the normal, specular by the reflection vector.
vec3 shade(Surface s, vec3 world, float sun_visibility) {
    vec3 v = normalize(frame.camera_position.xyz - world);
    SurfaceBrdf b = surface_brdf(s.base_color, s.metallic, s.roughness);
    vec3 color = sun_visibility *
                 shade_direct(b, s.n, v, frame.sun_direction.xyz, frame.sun_radiance.rgb);
    float n_dot_v = max(abs(dot(s.n, v)), 1e-4);
    vec3 r = reflect(-v, s.n);
    vec3 diffuse_ambient = mix(frame.ground_ambient.rgb, frame.sky_ambient.rgb, s.n.y * 0.5 + 0.5);
    vec3 specular_ambient = mix(frame.ground_ambient.rgb, frame.sky_ambient.rgb, r.y * 0.5 + 0.5);
    color += s.occlusion * (diffuse_ambient * b.diffuse_color +
                            specular_ambient * env_brdf_approx(b.f0, s.roughness, n_dot_v));
    return color + s.emissive;
}

// Everything but the normal and the roughness, from the material at `uv`.
Surface material_surface(vec4 base, vec2 uv) {
    Surface s;
    s.base_color = base.rgb;
    s.metallic = clamp(texture(metallic_roughness_texture, texture_uv(kTextureMetallicRoughness, uv)).b * material.metallic_factor,
                       0.0, 1.0);
    s.occlusion = 1.0 + material.occlusion_strength * (texture(occlusion_texture, texture_uv(kTextureOcclusion, uv)).r - 1.0);
    s.emissive = texture(emissive_texture, texture_uv(kTextureEmissive, uv)).rgb * material.emissive_factor.rgb;
    return s;
}

#endif
