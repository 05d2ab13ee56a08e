#version 460
// triangle_size (renderer/passes/triangle_size.h): per pixel, the screen-space area in px² of
// the triangle surface_id names (the prepass's winner; 0: nothing drawn, area 0), and the
// covered pixels counted per power-of-two bin of area.
//
// The triangle: its instance by binary search over the rows (surface base order), its three
// indices and positions from the scene's buffers, through view * model into view space. It is
// clipped against the near plane only (z = -znear, GLM's right-handed view looks down -z),
// never against the viewport, so the parts off screen count; the clipped polygon (at most four
// corners) goes through the projection to pixels, (ndc * 0.5 + 0.5) * viewport size, and its
// area is the shoelace sum.
//
// Precision: everything is kept relative to one corner. The other corners are view-space
// offsets, the model-view's 3x3 part times the object-space edge vectors, and each projected
// corner is the pixel offset from the first, derived from the offset's clip-space change
// (d.xy * w0 - c0.xy * d.w) / (w0 * (w0 + d.w)). Rounding then scales with the triangle, not
// with its distance from the world origin or the screen centre. Measured on the host in float
// against double (1280x720, 14000 triangles of 0.05 to 0.5 px² about 20 m from the eye and
// 30 m from the world origin): at worst 4e-6 of the area this way; subtracting absolute pixel
// positions errs by 2% typically and up to 100%.
#extension GL_GOOGLE_include_directive : require

#include "common/bindings.glsl"  // set 0: the frame uniforms; InstanceData

layout(local_size_x = 8, local_size_y = 8) in;

// Set 2 (set 1 is the material set bindings.glsl declares; nothing here reads it).
layout(set = 2, binding = 0) uniform usampler2D surface_ids;
layout(set = 2, binding = 1, r32f) uniform writeonly image2D sizes;
layout(set = 2, binding = 2, std430) readonly buffer Vertices {
    float vertex_words[];  // scene::Vertex: 12 floats, position first
};
layout(set = 2, binding = 3, std430) readonly buffer Indices {
    uint scene_indices[];
};
layout(set = 2, binding = 4, std430) readonly buffer Rows {
    uvec4 rows[];  // per instance: surface base, triangles, first index, vertex offset (int)
};
layout(set = 2, binding = 5, std430) readonly buffer SceneInstances {
    InstanceData scene_instances[];  // the scene's instance buffer (the frame set's is vertex-only)
};
layout(set = 2, binding = 6, std430) buffer Histogram {
    uint bins[];
};

layout(push_constant) uniform Push {
    uvec2 size;
    uint instances;
}
push;

// TriangleSizeResult's bins: floor(log2(area)) clamped to [MIN_EXPONENT, MAX_EXPONENT] (the
// pass defines both from TriangleSizeResult; these defaults are for the build-time check).
#ifndef MIN_EXPONENT
#define MIN_EXPONENT -10
#endif
#ifndef MAX_EXPONENT
#define MAX_EXPONENT 30
#endif
const int kMinExponent = MIN_EXPONENT;
const int kMaxExponent = MAX_EXPONENT;
const uint kBins = uint(kMaxExponent - kMinExponent + 1);
const uint kVertexWords = 12u;

shared uint group_bins[kBins];

// The last row whose base is at or below `index`; -1 when none.
int find_instance(uint index) {
    int lo = 0, hi = int(push.instances) - 1, found = -1;
    while (lo <= hi) {
        int mid = (lo + hi) / 2;
        if (rows[mid].x <= index) {
            found = mid;
            lo = mid + 1;
        } else {
            hi = mid - 1;
        }
    }
    return found;
}

vec3 position(uint index_slot, int vertex_offset) {
    uint at = uint(int(scene_indices[index_slot]) + vertex_offset) * kVertexWords;
    return vec3(vertex_words[at], vertex_words[at + 1u], vertex_words[at + 2u]);
}

// Area in px² of the view-space triangle origin + corner[k] (corner[0] = 0) after clipping
// against z = -znear.
float clipped_area(vec3 origin, vec3 corner[3]) {
    float front = -origin.z - frame.depth_params.x;  // corner k is in front when front >= z
    float d[3];
    for (int k = 0; k < 3; ++k) d[k] = front - corner[k].z;
    vec3 poly[4];  // one plane cuts a triangle into at most four corners
    int n = 0;
    for (int k = 0; k < 3; ++k) {
        int next = (k + 1) % 3;
        if (d[k] >= 0.0) poly[n++] = corner[k];
        if ((d[k] >= 0.0) != (d[next] >= 0.0))
            poly[n++] = mix(corner[k], corner[next], d[k] / (d[k] - d[next]));
    }
    if (n < 3) return 0.0;
    vec4 c0 = frame.projection * vec4(origin + poly[0], 1.0);
    vec2 half_size = 0.5 * frame.viewport.xy;
    vec2 s[4];  // pixel offsets from poly[0]
    for (int k = 1; k < n; ++k) {
        vec4 dc = frame.projection * vec4(poly[k] - poly[0], 0.0);
        s[k] = half_size * (dc.xy * c0.w - c0.xy * dc.w) / (c0.w * (c0.w + dc.w));
    }
    float twice = 0.0;
    for (int k = 1; k + 1 < n; ++k) twice += s[k].x * s[k + 1].y - s[k + 1].x * s[k].y;
    return 0.5 * abs(twice);
}

// The area of surface `index` (its id minus 1).
float surface_area(uint index) {
    int i = find_instance(index);
    if (i < 0) return 0.0;
    uvec4 row = rows[i];
    uint triangle = index - row.x;
    if (triangle >= row.y) return 0.0;
    uint first = row.z + 3u * triangle;
    int offset = int(row.w);
    vec3 p0 = position(first, offset);
    vec3 p1 = position(first + 1u, offset);
    vec3 p2 = position(first + 2u, offset);
    mat4 model_view = frame.view * scene_instances[i].model;
    vec3 origin = (model_view * vec4(p0, 1.0)).xyz;
    mat3 linear = mat3(model_view);
    vec3 corner[3] = vec3[3](vec3(0.0), linear * (p1 - p0), linear * (p2 - p0));
    return clipped_area(origin, corner);
}

// floor(log2(area)) from the float's exponent bits (exact, unlike log2), clamped: 0 and
// denormals fall in the first bin, infinity in the last.
uint bin_of(float area) {
    int exponent = int((floatBitsToUint(area) >> 23) & 0xffu) - 127;
    return uint(clamp(exponent, kMinExponent, kMaxExponent) - kMinExponent);
}

void main() {
    uint lane = gl_LocalInvocationIndex;
    if (lane < kBins) group_bins[lane] = 0u;
    barrier();
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (all(lessThan(gl_GlobalInvocationID.xy, push.size))) {
        uint id = texelFetch(surface_ids, p, 0).r;
        float area = id == 0u ? 0.0 : surface_area(id - 1u);
        imageStore(sizes, p, vec4(area, 0.0, 0.0, 0.0));
        if (id != 0u) atomicAdd(group_bins[bin_of(area)], 1u);
    }
    barrier();
    // One global atomic per non-empty bin and group, not one per pixel.
    if (lane < kBins && group_bins[lane] != 0u) atomicAdd(bins[lane], group_bins[lane]);
}
