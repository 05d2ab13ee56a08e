#pragma once
// The fragment shader of the layer's measurement draw (issue 28): the application's vertex
// stages with a fragment shader of the layer's own that counts every fragment rasterized. It is
// generated per pipeline so that its Input interface mirrors the last pre-rasterization stage's
// user outputs: with a shader that declares no inputs, the Khronos validation layer warns of
// every output "not consumed by fragment shader" (UNASSIGNED-CoreValidation-Shader-
// OutputNotConsumed). Pure SPIR-V, no Vulkan, no SPIRV-Tools.
//
// The module:
// - one Input variable per user output of the entry (an Output variable of its interface that
//   is not BuiltIn and not a block of BuiltIn members such as gl_PerVertex), of an identical type
//   (the whole type graph copied: scalars, vectors, matrices, arrays with their length
//   constants, structs) with the output's Location and Component decorations, and a block's
//   Block decoration and member Location / Component decorations; nothing else (no Offset,
//   ArrayStride, interpolation or precision decorations). A spec-constant array length is
//   copied with its SpecId: pass the stage's VkSpecializationInfo to this shader too;
// - Flat on every input that holds an integer or a 64-bit float: the variable, or each such
//   member of a struct (or block) type;
// - the capabilities its types need, carried from the stage's (Float64, Int64, Int16, Float16,
//   Int8, StorageInputOutput16, and SPV_KHR_16bit_storage / the AMD 16-bit extensions where
//   the stage declares them), Shader always;
// - entry point "main", OriginUpperLeft, no outputs, no discard, no early tests: the body is
//   DrawCounters.rasterized += 1 and counts[(y * width + x) * 4 + 2] += 1 for the pixel (x, y) =
//   uvec2(gl_FragCoord.xy) inside width x height, else counts[0] += 0 (instrument.h's buffers,
//   bindings and atomics: relaxed, Device scope, the GLSL450 memory model);
// - the stage's SPIR-V version (at least 1.0); below 1.3 the StorageBuffer extension, from 1.4
//   on every global in the interface. The inputs are never read (valid: unused inputs).
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "layer/spirv/instrument.h"

namespace ds::layer {

// `stage`'s entry point `entry` is the last pre-rasterization stage: Vertex,
// TessellationEvaluation or Geometry. Throws ds::Error (one sentence) for a malformed module
// (or an output type it cannot copy), no entry point of those models named `entry`, or equal
// bindings in `b`.
std::vector<uint32_t> measurement_fragment(std::span<const uint32_t> stage, std::string_view entry,
                                           const CounterBindings& b);
// The same module without counters or FragCoord: `main` does nothing. What the Z-fight and
// EQUAL re-draws of a pipeline without a fragment shader rewrite (survival.h).
std::vector<uint32_t> passthrough_fragment(std::span<const uint32_t> stage,
                                           std::string_view entry);

}  // namespace ds::layer
