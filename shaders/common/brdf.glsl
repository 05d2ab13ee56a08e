// PBR-lite: GGX specular (height-correlated Smith visibility, Schlick Fresnel) + Lambert.
#ifndef DS_BRDF_GLSL
#define DS_BRDF_GLSL

const float kPi = 3.14159265358979;

float d_ggx(float n_dot_h, float alpha) {
    float a2 = alpha * alpha;
    float f = (n_dot_h * a2 - n_dot_h) * n_dot_h + 1.0;
    return a2 / (kPi * f * f);
}

float v_smith_ggx_correlated(float n_dot_v, float n_dot_l, float alpha) {
    float a2 = alpha * alpha;
    float gv = n_dot_l * sqrt(n_dot_v * n_dot_v * (1.0 - a2) + a2);
    float gl = n_dot_v * sqrt(n_dot_l * n_dot_l * (1.0 - a2) + a2);
    return 0.5 / max(gv + gl, 1e-6);
}

vec3 f_schlick(vec3 f0, float v_dot_h) {
    return f0 + (1.0 - f0) * pow(1.0 - v_dot_h, 5.0);
}

struct SurfaceBrdf {
    vec3 diffuse_color;  // base * (1 - metallic)
    vec3 f0;             // 0.04 for dielectrics, base colour for metals
    float alpha;         // roughness^2, clamped so highlights never become a singularity
};

SurfaceBrdf surface_brdf(vec3 base_color, float metallic, float perceptual_roughness) {
    SurfaceBrdf s;
    s.diffuse_color = base_color * (1.0 - metallic);
    s.f0 = mix(vec3(0.04), base_color, metallic);
    float r = clamp(perceptual_roughness, 0.045, 1.0);
    s.alpha = r * r;
    return s;
}

// Outgoing radiance towards V from a directional light of radiance `light` along L.
vec3 shade_direct(SurfaceBrdf s, vec3 n, vec3 v, vec3 l, vec3 light) {
    float n_dot_l = clamp(dot(n, l), 0.0, 1.0);
    if (n_dot_l <= 0.0) return vec3(0.0);
    vec3 h = normalize(v + l);
    float n_dot_v = max(abs(dot(n, v)), 1e-4);
    float n_dot_h = clamp(dot(n, h), 0.0, 1.0);
    float v_dot_h = clamp(dot(v, h), 0.0, 1.0);
    vec3 f = f_schlick(s.f0, v_dot_h);
    vec3 specular = d_ggx(n_dot_h, s.alpha) * v_smith_ggx_correlated(n_dot_v, n_dot_l, s.alpha) * f;
    vec3 diffuse = (1.0 - f) * s.diffuse_color / kPi;
    return (diffuse + specular) * light * n_dot_l;
}

// Karis' analytic fit of the split-sum environment BRDF (no lookup texture needed).
vec3 env_brdf_approx(vec3 f0, float perceptual_roughness, float n_dot_v) {
    const vec4 c0 = vec4(-1.0, -0.0275, -0.572, 0.022);
    const vec4 c1 = vec4(1.0, 0.0425, 1.04, -0.04);
    vec4 r = perceptual_roughness * c0 + c1;
    float a004 = min(r.x * r.x, exp2(-9.28 * n_dot_v)) * r.x + r.y;
    vec2 ab = vec2(-1.04, 1.04) * a004 + r.zw;
    return f0 * ab.x + ab.y;
}

#endif
