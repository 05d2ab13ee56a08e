// Exposure + tonemapping. The tonemap pass writes an _SRGB target, so it outputs linear
// values and the hardware encodes.
#ifndef DS_TONEMAP_GLSL
#define DS_TONEMAP_GLSL

// Narkowicz's fit of the ACES filmic curve (RRT + ODT).
vec3 aces_fitted(vec3 x) {
    const float a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
    return clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0, 1.0);
}

vec3 tonemap(vec3 radiance, float exposure) {
    return aces_fitted(max(radiance, vec3(0.0)) * exposure);
}

#endif
