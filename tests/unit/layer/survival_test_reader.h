#pragma once
// A survival shader (layer/spirv/survival.h) read back for its tests: where it writes, where
// its survival code sits, what remains of the application's discards and execution modes.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace ds::layer::testing {

struct SurvivalFacts {
    size_t output_variables = 0;      // OpVariable of class Output
    size_t output_pointer_types = 0;  // OpTypePointer of class Output
    // Writes (OpStore, OpAtomicStore, OpCopyMemory(Sized), OpAtomicFlagClear, atomic
    // read-modify-writes, OpImageWrite) whose target is neither of class Function, Private or
    // Workgroup nor in one of the variables of the layer's descriptor set.
    size_t foreign_writes = 0;
    size_t atomic_loads = 0;  // OpAtomicLoad
    // For each block of the entry's function that ends in OpReturn / OpReturnValue: the
    // OpAtomicUMin on ZPixels in it, and whether an OpStore into Records comes just before the
    // return.
    std::vector<size_t> umin_per_return;
    size_t returns_after_record = 0;
    size_t umin_elsewhere = 0;  // OpAtomicUMin on ZPixels in any other block
    size_t discards = 0;        // OpKill, OpTerminateInvocation, OpDemoteToHelperInvocation
    bool early_fragment_tests = false;
    size_t depth_modes = 0;  // DepthReplacing, DepthGreater, DepthLess, DepthUnchanged,
                             // StencilRefReplacingEXT (any entry)
};

// The facts of `spirv`: the layer's set and buffer bindings as survival.h's SurvivalBindings.
SurvivalFacts read_survival(std::span<const uint32_t> spirv, uint32_t set = 7,
                            uint32_t zpixel_binding = 2, uint32_t record_binding = 3,
                            const std::string& entry = "main");
// The OpReturn / OpReturnValue of the function of Fragment entry point `entry`.
size_t entry_returns(std::span<const uint32_t> spirv, const std::string& entry = "main");

}  // namespace ds::layer::testing
