#version 460
#extension GL_GOOGLE_include_directive : require
// prepass_mode=depth: world-space normals reconstructed from the scene depth, for the
// screen-space passes that read normals (gtao, its filter, contact shadows) when the Z-only
// prepass wrote none. Per pixel: the view-space positions of the pixel and its four
// neighbours from the depth; along each axis the neighbour whose linear depth is closer to
// the pixel's (the smaller |dz|) gives the tangent, so a silhouette neighbour on another
// surface is not used (the 5-tap choice of Mara et al. / Turanszki's "improved normal
// reconstruction from depth"); the normal is their cross product, turned towards the camera,
// taken to world space. Geometric, not normal-mapped: the G-buffer's normals are the
// shading normals, so AO differs slightly between the two prepass modes.
// Output as the prepass's: n * 0.5 + 0.5, alpha 1; background (0.5, 0.5, 0.5, 0).

layout(local_size_x = 8, local_size_y = 8) in;

#include "common/frame.glsl"

layout(set = 1, binding = 0) uniform sampler2D depth_tex;  // the resolved scene depth
// RGBA8: storage is guaranteed for it on every Vulkan device (A2B10G10R10 is optional), and
// 8 bits per axis is well below what AO's cosine terms resolve.
layout(set = 1, binding = 1, rgba8) uniform writeonly image2D normals_out;

ivec2 g_size;

bool background(float d) {
    return frame.depth_params.z > 0.5 ? d <= 0.0 : d >= 1.0;
}

// View-space position of pixel `px` (its centre) at depth value `d`: the view ray scaled to
// z = -1 times the linear distance (exact for both depth conventions). A perspective
// projection's z and w rows do not involve x and y, so neither do its inverse's: the ray is
// affine in the NDC position, two multiply-adds per pixel instead of a matrix product.
vec3 view_position(ivec2 px, float d) {
    vec2 ndc = (vec2(px) + 0.5) / vec2(g_size) * 2.0 - 1.0;
    vec4 k = frame.inverse_projection[2] * 0.5 + frame.inverse_projection[3];  // ndc.xy = 0
    vec3 p = ndc.x * frame.inverse_projection[0].xyz + ndc.y * frame.inverse_projection[1].xyz +
             k.xyz;
    return p / -k.z * linear_depth(d);
}

// The tangent along one axis: towards the neighbour (at -step or +step) nearer in depth, as
// a difference pointing along +step. `ok` is false when neither neighbour is surface. Each
// neighbour's depth is fetched once.
vec3 tangent(ivec2 px, ivec2 step, vec3 p, out bool ok) {
    ivec2 a = px - step, b = px + step;
    bool in_a = all(greaterThanEqual(a, ivec2(0))), in_b = all(lessThan(b, g_size));
    float da = in_a ? texelFetch(depth_tex, a, 0).r : 0.0;
    float db = in_b ? texelFetch(depth_tex, b, 0).r : 0.0;
    bool has_a = in_a && !background(da), has_b = in_b && !background(db);
    ok = has_a || has_b;
    vec3 pa = has_a ? view_position(a, da) : p;
    vec3 pb = has_b ? view_position(b, db) : p;
    bool use_b = has_b && (!has_a || abs(pb.z - p.z) <= abs(p.z - pa.z));
    return use_b ? pb - p : p - pa;
}

void main() {
    g_size = textureSize(depth_tex, 0);
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(px, g_size))) return;
    float d = texelFetch(depth_tex, px, 0).r;
    if (background(d)) {
        imageStore(normals_out, px, vec4(0.5, 0.5, 0.5, 0.0));
        return;
    }
    vec3 p = view_position(px, d);
    bool ok_x, ok_y;
    vec3 tx = tangent(px, ivec2(1, 0), p, ok_x);
    vec3 ty = tangent(px, ivec2(0, 1), p, ok_y);
    vec3 n = cross(tx, ty);
    // A lone pixel (no surface neighbour on an axis) or a degenerate pair: face the camera.
    float len2 = dot(n, n);
    n = (ok_x && ok_y && len2 > 1e-30) ? n * inversesqrt(len2) : normalize(-p);
    if (dot(n, -p) < 0.0) n = -n;  // the side the camera sees, as the prepass's facing()
    // frame.view is rigid: its rotation's transpose takes directions back to world space.
    vec3 world = transpose(mat3(frame.view)) * n;
    imageStore(normals_out, px, vec4(world * 0.5 + 0.5, 1.0));
}
