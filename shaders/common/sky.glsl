// Procedural sky radiance: a zenith-horizon-ground gradient, a glow around the sun and the
// sun's disc (about 1 degree across, larger than the real 0.53 so it reads at small sizes).
#ifndef DS_SKY_GLSL
#define DS_SKY_GLSL

#include "frame.glsl"

vec3 sky_radiance(vec3 dir) {
    const vec3 zenith = vec3(0.10, 0.26, 0.72);
    const vec3 horizon = vec3(0.52, 0.64, 0.82);
    const vec3 ground = vec3(0.24, 0.22, 0.20);
    float h = clamp(dir.y, -1.0, 1.0);
    vec3 c = h >= 0.0 ? mix(horizon, zenith, sqrt(h)) : mix(horizon, ground, sqrt(-h));
    float mu = dot(dir, frame.sun_direction.xyz);
    c += frame.sun_radiance.rgb * (0.03 * pow(max(mu, 0.0), 48.0));
    c += frame.sun_radiance.rgb * (12.0 * smoothstep(0.99985, 0.99992, mu));
    return c;
}

#endif
