#version 460
#extension GL_GOOGLE_include_directive : require
// Upsampling and temporal accumulation of the filtered AO, per full-resolution pixel.
//
// Upsampling: ao_spatial's output may have gtao's reduced resolution; it is packed (AO, view
// distance, octahedral view-space normal) per texel. The pixel blends the 2x2 texels around
// it with bilinear weights, each also weighted by this pixel's distance from the texel's
// tangent plane (relative to the view distance) and by the agreement of normals (dot^8), as
// ao_spatial weighs its taps: no AO crosses a depth edge or a corner. At equal resolutions
// the pixel's own texel has bilinear weight 1 and the others 0: a copy.
//
// Temporal: the pixel's surface point is reprojected into the previous frame
// (previous_view_projection); the history there is blended in when it saw the same surface.
// The history image stores (AO, view distance) so a disocclusion shows up as a distance
// mismatch, tap by tap of the bilinear footprint: taps of another surface drop out, and with
// none left the pixel restarts from the current value. Without a valid history (first frame,
// resize, camera cut: the graph says so) the output is the current value.
//
// Writes the AO forward reads and the next frame's history.

layout(local_size_x = 8, local_size_y = 8) in;

#include "common/frame.glsl"
#include "common/screen_space.glsl"

layout(set = 1, binding = 0) uniform sampler2D depth_tex;
layout(set = 1, binding = 1) uniform sampler2D normal_tex;   // world normals, n * 0.5 + 0.5
layout(set = 1, binding = 2) uniform sampler2D ao_current;   // ao_spatial's output, packed
layout(set = 1, binding = 3) uniform sampler2D history_in;   // rg: AO, view distance (0: none)
layout(set = 1, binding = 4, r8) uniform writeonly image2D ao_out;
layout(set = 1, binding = 5, rg16f) uniform writeonly image2D history_out;

layout(push_constant) uniform Params {
    uint history_valid;       // 0: the previous frame's history holds nothing usable
    float history_weight;     // share of the history in the blend (0.9: ~10-frame average)
    float depth_tolerance;    // accepted relative distance mismatch of a history tap
    float plane_tolerance;    // upsampling: tangent-plane distance / view distance of weight 1/e
} params;

// The current AO at full-resolution pixel px (view-space position P; N, its view normal, is
// fetched only when needed). Fast path: when the 2x2 texels all lie at this pixel's distance
// and their normals agree, the pixel is inside one smooth surface and plain bilinear weights
// are the answer; only near an edge is each texel weighed (most pixels are not, and the normal
// fetch, the decodes and the exponentials are what a CPU device pays for).
float upsample_current(ivec2 px, vec3 P, RayBasis rays) {
    ivec2 full_size = ivec2(frame.viewport.xy);
    ivec2 size = textureSize(ao_current, 0);
    vec2 pos = (vec2(px) + 0.5) * vec2(size) / vec2(full_size) - 0.5;
    ivec2 base = clamp(ivec2(floor(pos)), ivec2(0), max(size - 2, ivec2(0)));
    vec2 f = clamp(pos - vec2(base), 0.0, 1.0);  // at the border: the edge texels
    vec4 taps[4];
    float z = -P.z, smooth_tolerance = 0.5 * params.plane_tolerance * z;
    bool smooth_surface = true;
    for (int i = 0; i < 4; ++i) {
        taps[i] = texelFetch(ao_current, min(base + ivec2(i & 1, i >> 1), size - 1), 0);
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

    float d = texelFetch(depth_tex, px, 0).r;
    if (is_background(d)) {
        imageStore(ao_out, px, vec4(1.0));
        imageStore(history_out, px, vec4(1.0, 0.0, 0.0, 0.0));  // distance 0: no surface
        return;
    }
    RayBasis rays = ray_basis(px, frame.viewport.zw);
    vec3 P = rays.ray * linear_depth(d);
    // On the 8-bit grid of ao_out, as ao_filtered was when it was R8: under a still camera
    // the blend of a value with its own 16-bit history then rounds back to the same byte, so
    // every later frame is bit-identical to the first (captures, compare and replay rely on
    // it). Unquantised, a value next to a rounding boundary could flip by one step.
    float current = round(upsample_current(px, P, rays) * 255.0) / 255.0;
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
