#pragma once
// What a fragment shader's SPIR-V says about early fragment tests (issue 11 part 3): a small
// reader of the word stream (5-word header, then instructions of (word count << 16 | opcode)),
// no SPIRV-Tools. The verdict adds the one pipeline state that matters (alpha to coverage).
#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace ds::spirv {

struct FragmentFacts {
    bool early_fragment_tests = false;  // OpExecutionMode EarlyFragmentTests
    bool depth_replacing = false;       // OpExecutionMode DepthReplacing
    bool writes_depth = false;          // a store to the FragDepth builtin (or DepthReplacing)
    bool writes_sample_mask = false;    // a store to the SampleMask builtin
    bool discards = false;  // OpKill, OpTerminateInvocation or OpDemoteToHelperInvocation
    // OpImageWrite, an atomic other than a load, or a store through a storage buffer, physical
    // storage buffer, image texel or BufferBlock uniform pointer.
    bool storage_writes = false;
};

// Throws ds::Error when `spirv` is not a SPIR-V module or has no Fragment entry point.
FragmentFacts read_fragment_facts(std::span<const uint32_t> spirv);

// "guaranteed", or "lost: " + the reasons in this order: depth write, sample mask write,
// discard, storage writes, alpha to coverage (pipeline state: coverage then depends on the
// shader's output, so many GPUs test depth late). EarlyFragmentTests guarantees early tests
// whatever the shader does (the spec runs them before it; a depth write is then ignored). An
// empty `fragment` (depth only) is "guaranteed": there is no shader to wait for.
std::string early_z_verdict(std::span<const uint32_t> fragment, bool alpha_to_coverage);
std::string early_z_verdict(const FragmentFacts& facts, bool alpha_to_coverage);

// Where a writing atomic instruction (`opcode`, a spv::Op) has its pointer: the index of that
// operand (2, after the result type and id; 0 for OpAtomicStore and OpAtomicFlagClear), or none
// for any other instruction (OpAtomicLoad among them).
std::optional<size_t> atomic_write_pointer(uint32_t opcode);

}  // namespace ds::spirv
