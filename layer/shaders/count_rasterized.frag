#version 450
// The layer's measurement draw: the application's vertex stages, depth and stencil tests off,
// no colour written; every fragment it rasterizes adds one to its draw's and its pixel's
// `rasterized` (layer/capture_resources.h's layout). Compiled for set 0; the layer rewrites
// the set to its slot (the device's last).
layout(set = 0, binding = 0, std430) buffer DrawCounters {
    uint shaded;
    uint discarded;
    uint rasterized;
    uint reserved;
} draw_counts;
layout(set = 0, binding = 1, std430) buffer PixelCounters {
    uint width;
    uint height;
    uint reserved0;
    uint reserved1;
    uint counts[];
} pixels;

void main() {
    atomicAdd(draw_counts.rasterized, 1u);
    uvec2 p = uvec2(gl_FragCoord.xy);
    if (p.x < pixels.width && p.y < pixels.height)
        atomicAdd(pixels.counts[(p.y * pixels.width + p.x) * 4u + 2u], 1u);
}
