#version 460
// equal_check (prepass on, depth_compare=equal): after forward, marks pixels the prepass
// covered where forward shaded nothing (holes: invariance, jitter or cutoff mismatch) and
// pixels forward shaded more than once (ties: coplanar surfaces both passing EQUAL), from
// forward's per-pixel fragment counts; appends (winning surface, mark) for the report.

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform usampler2D forward_counts;
layout(set = 0, binding = 1) uniform sampler2D stored_depth;
layout(set = 0, binding = 2) uniform usampler2D surface_ids;
layout(set = 0, binding = 3, r32ui) uniform writeonly uimage2D marks;  // 0 ok, 1 hole, 2 tie
layout(set = 0, binding = 4, std430) buffer Result {
    uint holes;
    uint multiple;
    uint appended;  // records; past push.capacity they are dropped
    uint pad;
    uvec2 records[];  // surface id, mark
}
result;

layout(push_constant) uniform Push {
    uvec2 size;
    float far_depth;
    uint capacity;
}
push;

void main() {
    const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(p), push.size))) return;
    const uint shaded = texelFetch(forward_counts, p, 0).r;
    const bool covered = texelFetch(stored_depth, p, 0).r != push.far_depth;
    uint mark = 0u;
    if (covered && shaded == 0u) mark = 1u;
    if (shaded > 1u) mark = 2u;
    imageStore(marks, p, uvec4(mark));
    if (mark == 0u) return;
    if (mark == 1u) atomicAdd(result.holes, 1u);
    else atomicAdd(result.multiple, 1u);
    const uint i = atomicAdd(result.appended, 1u);
    if (i < push.capacity) result.records[i] = uvec2(texelFetch(surface_ids, p, 0).r, mark);
}
