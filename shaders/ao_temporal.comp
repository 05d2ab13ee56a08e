#version 460
#extension GL_GOOGLE_include_directive : require
// Temporal accumulation of the filtered AO at gtao's resolution, then the edge-aware upsample
// to the full-resolution `ao` forward reads: two dispatches of one pass (UPSAMPLE 0, then 1).
//
// Accumulation (UPSAMPLE 0, per AO texel): the texel's surface point (its source pixel's ray
// times the view distance ao_spatial carried along) is reprojected into the previous frame
// (previous_view_projection); the history there is blended in when it saw the same surface.
// The history is packed like ao_filtered (AO, view distance, octahedral view normal), so a
// disocclusion shows up as a distance mismatch tap by tap of the bilinear footprint (taps of
// another surface drop out; with none left the texel restarts from the current value), and the
// upsample needs no other input. Without a valid history (first frame, resize, camera cut: the
// graph says so) the result is the current value. Everything per texel, not per pixel: a
// quarter of the work at half resolution, and a CPU device pays per invocation.
//
// Upsample (UPSAMPLE 1, per pixel): the 2x2 history texels around the pixel with bilinear
// weights, each also weighted by this pixel's distance from the texel's tangent plane
// (relative to the view distance) and by the agreement of normals (dot^8), as ao_spatial
// weighs its taps: no AO crosses a depth edge or a corner. At equal resolutions the pixel's own
// texel has bilinear weight 1 and the others 0: a copy.
//
// A still camera gives bit-identical frames (captures, compare and replay rely on it): the
// history lookup snaps to the texel itself when the motion is below float noise, the blend of
// a 16-bit value with itself rounds back to it, and the upsample is a function of the history.

#ifndef UPSAMPLE
#define UPSAMPLE 0
#endif

layout(local_size_x = 8, local_size_y = 8) in;

#include "common/frame.glsl"
#include "common/screen_space.glsl"

layout(push_constant) uniform Params {
    uint history_valid;       // 0: the previous frame's history holds nothing usable
    float history_weight;     // share of the history in the blend (0.9: ~10-frame average)
    float depth_tolerance;    // accepted relative distance mismatch of a history tap
    float plane_tolerance;    // upsampling: tangent-plane distance / view distance of weight 1/e
} params;

#if UPSAMPLE == 0

layout(set = 1, binding = 0) uniform sampler2D ao_current;  // ao_spatial's output, packed
layout(set = 1, binding = 1) uniform sampler2D history_in;  // packed alike (distance 0: none)
layout(set = 1, binding = 2, rgba16f) uniform writeonly image2D history_out;

// The history at texel position `pos` (texel centres at integers), from the taps of its
// bilinear footprint that saw a surface at the expected distance. Returns false when none did
// (disocclusion, off screen).
bool sample_history(vec2 pos, float expected_distance, out float ao) {
    ivec2 size = textureSize(history_in, 0);
    // Float noise of a still camera's reprojection (~1e-4 texel) would blend a sliver of the
    // neighbours in and could move the 16-bit value by one step: take the texel itself.
    vec2 nearest = round(pos);
    if (all(lessThan(abs(pos - nearest), vec2(1e-3)))) pos = nearest;
    ivec2 base = ivec2(floor(pos));
    vec2 f = pos - vec2(base);
    float sum = 0.0, weight_sum = 0.0;
    for (int i = 0; i < 4; ++i) {
        ivec2 o = ivec2(i & 1, i >> 1);
        ivec2 q = base + o;
        if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
        vec2 bilinear = mix(1.0 - f, f, vec2(o));
        float w = bilinear.x * bilinear.y;
        if (w == 0.0) continue;  // the snapped case: one fetch
        vec2 h = texelFetch(history_in, q, 0).rg;
        if (!(h.g > 0.0) ||
            abs(h.g - expected_distance) > params.depth_tolerance * expected_distance)
            continue;
        sum += w * h.r;
        weight_sum += w;
    }
    ao = weight_sum > 1e-3 ? sum / weight_sum : 0.0;
    return weight_sum > 1e-3;
}

void main() {
    ivec2 o = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(history_out);
    if (any(greaterThanEqual(o, size))) return;
    vec4 current = texelFetch(ao_current, o, 0);
    if (!(current.y > 0.0)) {  // sky: distance 0 marks it for the next frame and the upsample
        imageStore(history_out, o, vec4(1.0, 0.0, 0.0, 0.0));
        return;
    }
    float result = current.x;
    if (params.history_valid != 0u) {
        ivec2 full_size = ivec2(frame.viewport.xy);
        ivec2 px = ao_source_pixel(o, size, full_size);
        vec2 uv = (vec2(px) + 0.5) * frame.viewport.zw;
        vec3 P = view_ray(uv) * current.y;
        // World position through the rigid view transform's inverse (transpose of the
        // rotation), then last frame's camera. For a perspective projection clip.w is the
        // view distance, which the history stored.
        vec3 world = transpose(mat3(frame.view)) * (P - frame.view[3].xyz);
        vec4 clip = frame.previous_view_projection * vec4(world, 1.0);
        // The motion in full-resolution pixels, scaled to texels and added to this texel: the
        // texel grid need not be aligned with the pixel grid (ao_source_pixel), its spacing is.
        vec2 motion = ((clip.xy / clip.w * 0.5 + 0.5) - uv) * vec2(size);
        float history_ao;
        if (clip.w > 0.0 && sample_history(vec2(o) + motion, clip.w, history_ao))
            result = mix(current.x, history_ao, params.history_weight);
    }
    imageStore(history_out, o, vec4(result, current.yzw));
}

#else  // UPSAMPLE

layout(set = 1, binding = 0) uniform sampler2D depth_tex;
layout(set = 1, binding = 1) uniform sampler2D normal_tex;  // world normals, n * 0.5 + 0.5
layout(set = 1, binding = 2) uniform sampler2D ao_history;  // this frame's accumulated AO
layout(set = 1, binding = 3, r8) uniform writeonly image2D ao_out;

// The AO at full-resolution pixel px (view-space position P; N, its view normal, is fetched
// only when needed). Fast path: when the 2x2 texels all lie at this pixel's distance and
// their normals agree, the pixel is inside one smooth surface and plain bilinear weights are
// the answer; only near an edge is each texel weighed (most pixels are not, and the normal
// fetch, the decodes and the exponentials are what a CPU device pays for).
float upsample(ivec2 px, vec3 P, RayBasis rays) {
    ivec2 full_size = ivec2(frame.viewport.xy);
    ivec2 size = textureSize(ao_history, 0);
    vec2 pos = (vec2(px) + 0.5) * vec2(size) / vec2(full_size) - 0.5;
    ivec2 base = clamp(ivec2(floor(pos)), ivec2(0), max(size - 2, ivec2(0)));
    vec2 f = clamp(pos - vec2(base), 0.0, 1.0);  // at the border: the edge texels
    vec4 taps[4];
    float z = -P.z, smooth_tolerance = 0.5 * params.plane_tolerance * z;
    bool smooth_surface = true;
    for (int i = 0; i < 4; ++i) {
        taps[i] = texelFetch(ao_history, min(base + ivec2(i & 1, i >> 1), size - 1), 0);
        smooth_surface = smooth_surface && abs(taps[i].y - z) < smooth_tolerance &&
                         all(lessThan(abs(taps[i].zw - taps[0].zw), vec2(0.05)));
    }
    vec4 bilinear = vec4((1.0 - f.x) * (1.0 - f.y), f.x * (1.0 - f.y), (1.0 - f.x) * f.y, f.x * f.y);
    if (smooth_surface) return dot(bilinear, vec4(taps[0].x, taps[1].x, taps[2].x, taps[3].x));

    vec3 N = world_to_view_dir(decode_normal(texelFetch(normal_tex, px, 0).xyz));
    float inv_tolerance = 1.0 / max(params.plane_tolerance * z, 1e-6);
    float sum = 0.0, weight_sum = 0.0;
    float best = 1.0, best_weight = 0.0;  // the best-matching texel, if none gets a weight
    for (int i = 0; i < 4; ++i) {
        vec4 tap = taps[i];
        if (!(tap.y > 0.0)) continue;  // sky
        ivec2 q = min(base + ivec2(i & 1, i >> 1), size - 1);
        vec3 n = oct_decode(tap.zw);
        vec3 tap_position = basis_ray(rays, vec2(ao_source_pixel(q, size, full_size) - px)) * tap.y;
        float plane = dot(P - tap_position, n) * inv_tolerance;
        float c = max(dot(n, N), 0.0);
        float c2 = c * c, c4 = c2 * c2;
        float similar = exp(-plane * plane) * c4 * c4;
        float w = bilinear[i] * similar;
        sum += w * tap.x;
        weight_sum += w;
        if (similar > best_weight) {
            best = tap.x;
            best_weight = similar;
        }
    }
    // No texel around of this surface (a feature thinner than a texel): the most similar one.
    return weight_sum > 1e-4 ? sum / weight_sum : best;
}

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(ao_out);
    if (any(greaterThanEqual(px, size))) return;
    float d = texelFetch(depth_tex, px, 0).r;
    if (is_background(d)) {
        imageStore(ao_out, px, vec4(1.0));
        return;
    }
    RayBasis rays = ray_basis(px, frame.viewport.zw);
    vec3 P = rays.ray * linear_depth(d);
    imageStore(ao_out, px, vec4(upsample(px, P, rays)));
}

#endif
