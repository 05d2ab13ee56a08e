// Tangent-space normal mapping.
#ifndef DS_NORMAL_GLSL
#define DS_NORMAL_GLSL

// n: unit geometric normal; tangent.xyz interpolated tangent, tangent.w handedness;
// texel: normal map sample in [0,1]. A degenerate tangent (missing, zero, or parallel to n)
// keeps the vertex normal instead of producing NaN through normalize(0).
vec3 perturb_normal(vec3 n, vec4 tangent, vec3 texel, float scale) {
    vec3 t = tangent.xyz - n * dot(n, tangent.xyz);  // Gram-Schmidt against n
    float t_len2 = dot(t, t);
    if (!(t_len2 > 1e-10)) return n;  // also catches NaN tangents
    t *= inversesqrt(t_len2);
    vec3 b = cross(n, t) * (tangent.w < 0.0 ? -1.0 : 1.0);
    vec3 m = texel * 2.0 - 1.0;
    m.xy *= scale;
    vec3 p = mat3(t, b, n) * m;
    float p_len2 = dot(p, p);
    return p_len2 > 1e-10 ? p * inversesqrt(p_len2) : n;
}

#endif
