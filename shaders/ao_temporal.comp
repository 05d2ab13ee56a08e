#version 460
#extension GL_GOOGLE_include_directive : require
// Temporal accumulation of the filtered AO. Each pixel's surface point is reprojected into the
// previous frame (previous_view_projection); the history there is blended in when it saw the
// same surface. The history image stores (AO, view distance) so a disocclusion shows up as a
// distance mismatch, tap by tap of the bilinear footprint: taps of another surface drop out,
// and with none left the pixel restarts from the current value. Without a valid history
// (first frame, resize, camera cut: the graph says so) the output is the current value.
//
// Writes the AO forward reads and the next frame's history.

layout(local_size_x = 8, local_size_y = 8) in;

#include "common/frame.glsl"
#include "common/screen_space.glsl"

layout(set = 1, binding = 0) uniform sampler2D depth_tex;
layout(set = 1, binding = 1) uniform sampler2D ao_current;   // ao_spatial's output
layout(set = 1, binding = 2) uniform sampler2D history_in;   // rg: AO, view distance (0: none)
layout(set = 1, binding = 3, r8) uniform writeonly image2D ao_out;
layout(set = 1, binding = 4, rg16f) uniform writeonly image2D history_out;

layout(push_constant) uniform Params {
    uint history_valid;       // 0: the previous frame's history holds nothing usable
    float history_weight;     // share of the history in the blend (0.9: ~10-frame average)
    float depth_tolerance;    // accepted relative distance mismatch of a history tap
} params;

// The history at previous-frame uv, from the taps of its bilinear footprint that saw a surface
// at the expected distance. Returns false when none did (disocclusion, off screen).
bool sample_history(vec2 uv, float expected_distance, out float ao) {
    ivec2 size = textureSize(history_in, 0);
    vec2 pos = uv * vec2(size) - 0.5;
    ivec2 base = ivec2(floor(pos));
    vec2 f = pos - vec2(base);
    float sum = 0.0, weight_sum = 0.0;
    for (int i = 0; i < 4; ++i) {
        ivec2 o = ivec2(i & 1, i >> 1);
        ivec2 q = base + o;
        if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
        vec2 h = texelFetch(history_in, q, 0).rg;
        if (!(h.g > 0.0) ||
            abs(h.g - expected_distance) > params.depth_tolerance * expected_distance)
            continue;
        vec2 bilinear = mix(1.0 - f, f, vec2(o));
        float w = bilinear.x * bilinear.y;
        sum += w * h.r;
        weight_sum += w;
    }
    ao = weight_sum > 1e-3 ? sum / weight_sum : 0.0;
    return weight_sum > 1e-3;
}

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(ao_out);
    if (any(greaterThanEqual(px, size))) return;
    vec2 inv_size = 1.0 / vec2(textureSize(depth_tex, 0));

    float d = texelFetch(depth_tex, px, 0).r;
    if (is_background(d)) {
        imageStore(ao_out, px, vec4(1.0));
        imageStore(history_out, px, vec4(1.0, 0.0, 0.0, 0.0));  // distance 0: no surface
        return;
    }
    float current = texelFetch(ao_current, px, 0).r;
    vec3 P = view_position_at(px, inv_size, d);
    float result = current;
    if (params.history_valid != 0u) {
        // World position through the rigid view transform's inverse (transpose of the
        // rotation), then last frame's camera. For a perspective projection clip.w is the
        // view distance, which the history stored.
        vec3 world = transpose(mat3(frame.view)) * (P - frame.view[3].xyz);
        vec4 clip = frame.previous_view_projection * vec4(world, 1.0);
        float history_ao;
        if (clip.w > 0.0 &&
            sample_history(clip.xy / clip.w * 0.5 + 0.5, clip.w, history_ao))
            result = mix(current, history_ao, params.history_weight);
    }
    imageStore(ao_out, px, vec4(result));
    imageStore(history_out, px, vec4(result, -P.z, 0.0, 0.0));
}
