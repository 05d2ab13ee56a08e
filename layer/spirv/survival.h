#pragma once
// The survival fragment shader (Z-fight detection and the EQUAL-prepass check): a copy of an
// application's fragment shader that records, where an invocation survives (reaches the return
// of its entry point), its depth into the layer's buffers, and that has no other effect on
// memory. The layer re-draws depth-writing draws with it in an attachment-less render pass, and
// EQUAL draws with it inside the application's pass. Pure SPIR-V, no Vulkan, no SPIRV-Tools.
//
// What the rewrite does (the layer must bind and size the buffers to match):
// - no other effect on memory (survival_memory.h): the outputs (FragDepth, SampleMask too)
//   become Private globals, the depth / stencil execution modes go, every write to memory goes
//   and every atomic read-modify-write on memory becomes an atomic load. Discards stay: they
//   end the invocation (a demoted helper's atomics and stores have no effect);
// - three StorageBuffer variables at (set, draw_binding), (set, zpixel_binding) and
//   (set, record_binding), below; FragCoord (the module's or a new one); with
//   instance_location, a Flat uint Input there (add_instance_output's, instance_output.h);
// - before every OpReturn / OpReturnValue of the entry point's function (not of the functions
//   it calls), with no new block (the control flow stays the application's), for the pixel
//   (x, y) = uvec2(gl_FragCoord.xy), z = gl_FragCoord.z, zb = floatBitsToUint(z),
//   inside = x < width && y < height, p = inside ? y * width + x : 0:
//     mode 1 (nearest, forward depth): atomicMin(words[2p], zb)
//     mode 2 (nearest, reverse depth): atomicMax(words[2p], zb)
//     mode 4 (EQUAL survivors):        atomicAdd(words[2p + 1], 1)
//     mode 3 (records): steps = the distance of z from near = words[2p] in steps of the depth
//       format (depth_bits 32: float ULPs, |zb - near|; 24 or 16: unorm steps,
//       |uint(z * L + 0.5) - uint(uintBitsToFloat(near) * L + 0.5)|, L = 2^bits - 1; a near
//       that is not a float in [0, 1] (nothing recorded: 0xFFFFFFFF) is no step away);
//       when steps <= max_steps: i = atomicAdd(Records.count, 1) and, if i < capacity, record
//       i + 1 = (p, DrawCounters.draw_id, instance, zb);
//   every invocation runs every atomic (adding 0, or min / max with the neutral value, where its
//   mode or pixel does not apply) and writes record 0, the scratch record, unless it records;
//   a pixel outside width x height works on words[0], words[1] likewise;
// - atomics relaxed; Device scope, or QueueFamily under the Vulkan memory model;
// - OpExecutionMode EarlyFragmentTests when asked (and absent);
// - SPIR-V < 1.3: OpExtension "SPV_KHR_storage_buffer_storage_class"; FragCoord and the
//   instance input join the entry's interface, the buffers too from SPIR-V 1.4 on.
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace ds::layer {

// Where the buffers live: one descriptor set the layer adds at `set`.
struct SurvivalBindings {
    uint32_t set = 7;
    uint32_t draw_binding = 0;    // DrawCounters (read: draw_id)
    uint32_t zpixel_binding = 2;  // ZPixels
    uint32_t record_binding = 3;  // Records
};
// GLSL equivalents (std430):
//   buffer DrawCounters { uint shaded; uint discarded; uint rasterized; uint draw_id; };
//   buffer ZPixels { uint width; uint height; uint params; uint mode; uint words[]; };
//     params = max_steps | (depth_bits << 16), depth_bits 32 (D32 float), 24 or 16 (unorm);
//     pixel p: words[2p] = nearest, words[2p + 1] = EQUAL survivors
//   buffer Records { uint count; uint capacity; uint pad0; uint pad1; uint words[]; };
//     record r at words[4r .. 4r + 3] = (p, draw_id, instance, floatBitsToUint(gl_FragCoord.z));
//     record 0 is scratch (written by everyone, never read), the real ones are 1..capacity

struct SurvivalOptions {
    // The Location of a Flat uint input holding the instance (add_instance_output's);
    // UINT32_MAX: none, every record's instance is 0xFFFFFFFF.
    uint32_t instance_location = UINT32_MAX;
    bool early_fragment_tests = false;  // add ExecutionMode EarlyFragmentTests (if absent)
};

// Throws ds::Error (one sentence) for a malformed module, no Fragment entry point named
// `entry`, a module that already uses descriptor set `b.set` (or an input at
// `o.instance_location`), or two equal bindings in `b`.
std::vector<uint32_t> survival_fragment(std::span<const uint32_t> fragment, std::string_view entry,
                                        const SurvivalBindings& b, const SurvivalOptions& o = {});

// Whether the module reads input attachments (it has an OpTypeImage of Dim SubpassData): such
// a shader cannot run outside its subpass. Throws ds::Error for a malformed module.
bool reads_input_attachments(std::span<const uint32_t> spirv);

}  // namespace ds::layer
