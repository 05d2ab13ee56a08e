#version 460
// The MSAA sample view (issue 15): every sample of a rectangle of the frame, after the frame:
// the winning surface (the prepass's per-sample surface_id), the depth and the HDR colour, into
// a host buffer. One invocation per pixel of the rectangle. Defines (default 0):
//   MULTISAMPLED=1  the images are multisampled (msaa > 1); else the single-sample ones
//   SURFACE_ID=1    binding 2 holds the surface ids (the prepass ran); else surface 0
#extension GL_GOOGLE_include_directive : require

#ifndef MULTISAMPLED
#define MULTISAMPLED 0
#endif
#ifndef SURFACE_ID
#define SURFACE_ID 0
#endif

layout(local_size_x = 8, local_size_y = 8) in;

#if MULTISAMPLED
layout(set = 0, binding = 0) uniform sampler2DMS depth_image;
layout(set = 0, binding = 1) uniform sampler2DMS color_image;
#if SURFACE_ID
layout(set = 0, binding = 2) uniform usampler2DMS surface_image;
#endif
#define FETCH(image, p, s) texelFetch(image, p, s)
#else
layout(set = 0, binding = 0) uniform sampler2D depth_image;
layout(set = 0, binding = 1) uniform sampler2D color_image;
#if SURFACE_ID
layout(set = 0, binding = 2) uniform usampler2D surface_image;
#endif
#define FETCH(image, p, s) texelFetch(image, p, 0)
#endif

struct Sample {  // passes::SampleRecord
    uint surface;
    float depth;
    uint pad0, pad1;
    vec4 color;
};
layout(set = 0, binding = 3, std430) writeonly buffer Samples {
    Sample samples[];
};

layout(push_constant) uniform Push {
    ivec2 origin;  // the rectangle's top-left pixel
    uvec2 size;
    int sample_count;
} push;

void main() {
    const uvec2 q = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(q, push.size))) return;
    const ivec2 p = push.origin + ivec2(q);
    const uint base = (q.y * push.size.x + q.x) * uint(push.sample_count);
    for (int s = 0; s < push.sample_count; ++s) {
        Sample r;
#if SURFACE_ID
        r.surface = FETCH(surface_image, p, s).r;
#else
        r.surface = 0u;
#endif
        r.depth = FETCH(depth_image, p, s).r;
        r.pad0 = 0u;
        r.pad1 = 0u;
        r.color = FETCH(color_image, p, s);
        samples[base + uint(s)] = r;
    }
}
