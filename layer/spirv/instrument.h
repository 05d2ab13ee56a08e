#pragma once
// The Vulkan layer's fragment shader rewrite (issue 28): a copy of an application's fragment
// shader that counts itself, with the semantics of depthscope's own shaders
// (shaders/common/count.glsl): one count per invocation that runs the entry point, one per
// discard / demote / terminate reached. Pure SPIR-V, no Vulkan, no SPIRV-Tools.
//
// What the rewrite does (the layer must bind and size the buffers to match):
// - two StorageBuffer variables at (set, draw_binding) and (set, pixel_binding), below;
// - at the start of the entry point's function: DrawCounters.shaded += 1 and
//   counts[pixel * 4 + 0] += 1; before every OpKill, OpTerminateInvocation and
//   OpDemoteToHelperInvocation(EXT) of ANY function of the module (a discard may sit in a called
//   function, or in a function of another Fragment entry point of the module, which then counts
//   into the same buffers): DrawCounters.discarded += 1 and counts[pixel * 4 + 1] += 1;
// - a pixel outside width x height adds 0 to counts[0] instead (no branch is added, so the
//   control flow stays the application's): PixelCounters must hold at least counts[0..3] even
//   for an empty size;
// - OpAtomicIAdd, relaxed; Device scope, or QueueFamily under the Vulkan memory model;
// - OpExecutionMode EarlyFragmentTests when the original had none and nothing that early tests
//   would change (discard, depth / sample mask / stencil reference write, storage writes): the
//   atomics would otherwise make the driver test depth late;
// - SPIR-V < 1.3: OpExtension "SPV_KHR_storage_buffer_storage_class" (no new capability);
//   SPIR-V >= 1.4: both buffers join the interface of each Fragment entry point that uses them.
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace ds::layer {

// Where the counters live: one descriptor set the layer adds at `set` (the last slot).
struct CounterBindings {
    uint32_t set = 7;
    uint32_t draw_binding = 0;   // storage buffer (dynamic offset per draw): DrawCounters
    uint32_t pixel_binding = 1;  // storage buffer (dynamic offset per render pass): PixelCounters
};
// GLSL equivalents (std430):
//   buffer DrawCounters  { uint shaded; uint discarded; uint rasterized; uint reserved; };
//   buffer PixelCounters { uint width; uint height; uint reserved0; uint reserved1; uint counts[];
//   }; pixel (x, y) = uvec2(gl_FragCoord.xy): counts[(y * width + x) * 4 + k], k = 0 shaded, 1
//   discarded (2 rasterized and 3 reserved are the layer's own measurement shader's).

struct InstrumentResult {
    std::vector<uint32_t> spirv;
    bool early_fragment_tests_added = false;
    uint32_t discard_sites = 0;  // OpKill / OpTerminateInvocation / OpDemoteToHelperInvocation
};

// Throws ds::Error (one sentence) for a malformed module, no Fragment entry point named `entry`,
// a module that already uses descriptor set `b.set`, or equal bindings in `b`.
// `alpha_to_coverage`: the pipeline turns the shader's alpha into coverage, so the depth test
// must stay after the shader (early tests would write depth for samples the coverage drops):
// EarlyFragmentTests is never added then.
InstrumentResult instrument_fragment(std::span<const uint32_t> spirv, std::string_view entry,
                                     const CounterBindings& b, bool alpha_to_coverage = false);

}  // namespace ds::layer
