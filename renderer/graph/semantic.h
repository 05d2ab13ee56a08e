#pragma once
// The semantic every graph image carries (DESIGN decision 7): how the viewer and the capture
// writer decode and show it. Built-in kinds have a decoder each in renderer/view; Scalar is
// any one-value image, shown as its graph::Display (display.h) says. Its own header, free of
// Vulkan, so the view library (renderer/view) can read it without the graph.
#include <cstdint>

namespace ds::graph {

enum class Semantic : uint8_t {
    ReverseZDepth,  // near 1, far 0
    ForwardZDepth,  // near 0, far 1
    ShadowDepth,
    EncodedNormal,  // n * 0.5 + 0.5 (A2B10G10R10)
    UnormScalar,    // roughness and other [0, 1] scalars
    AO,
    HdrColor,
    LdrColor,
    Count,      // u32 counters (exact per-pixel invocation counts)
    SurfaceId,  // u32 surface ids (0: nothing drawn; gpu_scene.h SurfaceTable)
    DepthStep,  // r: one depth step along the view ray, g: the ray distance (scene units)
    Other,
    Scalar,  // r: one value, shown as the image's graph::Display says (display.h)
};

}  // namespace ds::graph
