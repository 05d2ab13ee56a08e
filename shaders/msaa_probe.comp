#version 460
// msaa > 1, after the frame: counts edge pixels (the multisampled HDR colour's samples are
// not all equal: without sample shading a fragment writes one colour to every sample it
// covers, so only pixels where surfaces, or a surface and the sky, meet differ) and, when
// asked, copies every depth sample out (a multisampled image cannot be copied to a buffer).

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform sampler2DMS msaa_depth;
layout(set = 0, binding = 1) uniform sampler2DMS msaa_color;
layout(set = 0, binding = 2, std430) buffer Probe {
    uint edge_pixels;
    uint pad[3];
    float depth_samples[];  // per pixel, row 0 = top, `samples` consecutive
} probe;

layout(push_constant) uniform Push {
    uvec2 size;
    int samples;
    int copy_depth;
} push;

void main() {
    const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(p), push.size))) return;
    const vec4 first = texelFetch(msaa_color, p, 0);
    bool edge = false;
    for (int i = 1; i < push.samples; ++i)
        edge = edge || any(notEqual(texelFetch(msaa_color, p, i), first));
    if (edge) atomicAdd(probe.edge_pixels, 1u);
    if (push.copy_depth == 0) return;
    const uint base = (uint(p.y) * push.size.x + uint(p.x)) * uint(push.samples);
    for (int i = 0; i < push.samples; ++i)
        probe.depth_samples[base + uint(i)] = texelFetch(msaa_depth, p, i).r;
}
