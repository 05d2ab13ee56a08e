// Per-frame uniforms (set 0, binding 0). Must match ds::passes::FrameUniforms
// (renderer/passes/frame.h).
#ifndef DS_FRAME_GLSL
#define DS_FRAME_GLSL

layout(set = 0, binding = 0, std140) uniform FrameUniforms {
    mat4 view_projection;  // the one expression prepass and forward share
    mat4 view;
    mat4 projection;
    mat4 inverse_view_projection;
    mat4 inverse_projection;
    mat4 previous_view_projection;
    mat4 sun_view_projection;  // world -> shadow map clip space
    vec4 camera_position;      // xyz world
    vec4 sun_direction;        // xyz unit, towards the sun
    vec4 sun_radiance;         // rgb
    vec4 sky_ambient;          // rgb
    vec4 ground_ambient;       // rgb
    vec4 viewport;             // xy size in pixels, zw 1 / size
    vec4 depth_params;         // x znear, y zfar, z 1 = reverse-Z, w exposure
    vec4 alpha;                // x global alpha cutoff, < 0: each material's own; y 1:
                               // alpha_level0 (mask_alpha() samples level 0)
    uvec4 flags;               // x kFrame* bits, y frame number
} frame;

const uint kFrameShadows = 1u << 0;
const uint kFrameAO = 1u << 1;
const uint kFrameContactShadows = 1u << 2;
const uint kFrameReverseZ = 1u << 3;

bool frame_has(uint bit) { return (frame.flags.x & bit) != 0u; }

// View-space distance (positive) of a depth-buffer value, for either depth convention.
float linear_depth(float d) {
    float n = frame.depth_params.x, f = frame.depth_params.y;
    return frame.depth_params.z > 0.5 ? n * f / (n + d * (f - n))  // reverse-Z: d=1 near
                                      : n * f / (f - d * (f - n));  // d=0 near
}

// Scene units along the view ray through `ndc` (x, y in -1..1) per unit of depth-buffer value
// at d: d(depth)/d(distance) is n f / (z^2 (f - n)) in either convention, stretched by the
// ray's length per unit of view depth. Multiply a depth difference by it: subtracting two
// nearby distances would cancel in 32 bits.
float ray_units_per_depth(float d, vec2 ndc) {
    float n = frame.depth_params.x, f = frame.depth_params.y;
    float z = linear_depth(d);
    vec4 view = frame.inverse_projection * vec4(ndc, d, 1.0);
    vec3 v = view.xyz / view.w;
    return z * z * (f - n) / (n * f) * length(v) / max(abs(v.z), 1e-20);
}

#endif
