#version 460
// The inspector's read-back of one graph image: every texel as four floats, exactly what a
// shader sampling it sees (depth in r, u32 counts converted to float, UNORM in 0..1), into an
// RGBA32F image the renderer copies to the host. A multisampled image is read at one sample.
//   UINT_SOURCE  1: an integer image (u32 counts)
//   MULTISAMPLED 1: a multisampled image, read at push.sample

#ifndef UINT_SOURCE
#define UINT_SOURCE 0
#endif
#ifndef MULTISAMPLED
#define MULTISAMPLED 0
#endif

layout(local_size_x = 8, local_size_y = 8) in;

#if UINT_SOURCE && MULTISAMPLED
layout(set = 1, binding = 0) uniform usampler2DMS source;
#elif UINT_SOURCE
layout(set = 1, binding = 0) uniform usampler2D source;
#elif MULTISAMPLED
layout(set = 1, binding = 0) uniform sampler2DMS source;
#else
layout(set = 1, binding = 0) uniform sampler2D source;
#endif
layout(set = 1, binding = 1, rgba32f) uniform writeonly image2D texels;

layout(push_constant) uniform Push {
    int sample_index;
} push;

void main() {
    const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(texels)))) return;
#if MULTISAMPLED
    const vec4 v = vec4(texelFetch(source, p, push.sample_index));
#else
    const vec4 v = vec4(texelFetch(source, p, 0));
#endif
    imageStore(texels, p, v);
}
