// Pixel history (issue 11 part 4): the instrumented variant of a geometry pass's fragment
// shader appends one record per fragment that covers the chosen pixel. The replay draws with a
// one-pixel scissor, no depth attachment and one stand-in colour attachment for output 0 (the
// others become plain variables), so every fragment that runs here covers that pixel;
// helper invocations (derivatives) write nothing. The GPU's atomic order is not submission
// order: the host sorts the records (renderer/passes/pixel_history.cpp). Defines (default 0):
//   PIXEL_HISTORY=1        record (set 4).
//   PIXEL_HISTORY_DEPTH=1  also read the depth the pass starts from at this pixel (binding 1).
//   PIXEL_HISTORY_DST=1    also read the HDR colour the pass starts from (binding 2).
//   PIXEL_HISTORY_MSAA=1   those are multisampled; one invocation per sample (gl_SampleID).
// Must match passes::HistoryRecord.
#ifndef DS_PIXEL_HISTORY_GLSL
#define DS_PIXEL_HISTORY_GLSL

#ifndef PIXEL_HISTORY
#define PIXEL_HISTORY 0
#endif
#ifndef PIXEL_HISTORY_DEPTH
#define PIXEL_HISTORY_DEPTH 0
#endif
#ifndef PIXEL_HISTORY_DST
#define PIXEL_HISTORY_DST 0
#endif
#ifndef PIXEL_HISTORY_MSAA
#define PIXEL_HISTORY_MSAA 0
#endif

const uint kHistoryAlphaTested = 1u;
const uint kHistoryDiscarded = 2u;
const uint kHistoryColor = 4u;  // `color` is an HDR colour output

#if PIXEL_HISTORY
struct HistoryRecord {
    uint instance;
    uint primitive;
    uint sample_index;
    uint flags;
    float depth;        // gl_FragCoord.z
    float start_depth;  // PIXEL_HISTORY_DEPTH: the depth image before the pass
    float alpha;
    float cutoff;
    vec4 color;
    vec4 dst;  // PIXEL_HISTORY_DST: the HDR colour before the pass
};
layout(set = 4, binding = 0, std430) buffer PixelHistory {
    uint count;
    uint pad0, pad1, pad2;
    HistoryRecord records[];
}
history;
#if PIXEL_HISTORY_MSAA
#define HISTORY_SAMPLER sampler2DMS
#define HISTORY_SAMPLE gl_SampleID
#else
#define HISTORY_SAMPLER sampler2D
#define HISTORY_SAMPLE 0
#endif
#if PIXEL_HISTORY_DEPTH
layout(set = 4, binding = 1) uniform HISTORY_SAMPLER history_depth;
#endif
#if PIXEL_HISTORY_DST
layout(set = 4, binding = 2) uniform HISTORY_SAMPLER history_dst;
#endif
layout(location = 5) flat in uint in_history_instance;

void history_record(float alpha, float cutoff, uint flags, vec4 color) {
    if (gl_HelperInvocation) return;
    uint i = atomicAdd(history.count, 1u);
    if (i >= uint(history.records.length())) return;  // counted: the host sees the overflow
    HistoryRecord r;
    r.instance = in_history_instance;
    r.primitive = uint(gl_PrimitiveID);
    r.sample_index = uint(HISTORY_SAMPLE);
    r.flags = flags;
    r.depth = gl_FragCoord.z;
    r.start_depth = 0.0;
    r.alpha = alpha;
    r.cutoff = cutoff;
    r.color = color;
    r.dst = vec4(0.0);
    ivec2 pixel = ivec2(gl_FragCoord.xy);
#if PIXEL_HISTORY_DEPTH
    r.start_depth = texelFetch(history_depth, pixel, HISTORY_SAMPLE).r;
#endif
#if PIXEL_HISTORY_DST
    r.dst = texelFetch(history_dst, pixel, HISTORY_SAMPLE);
#endif
    history.records[i] = r;
}
#else
// Off: the calls and their arguments vanish, so the frame's shaders compile to what they were.
#define history_record(alpha, cutoff, flags, color)
#endif

#endif
