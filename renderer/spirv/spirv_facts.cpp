#include "renderer/spirv/spirv_facts.h"

#include <optional>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#define SPV_ENABLE_UTILITY_CODE
#include <glslang/SPIRV/spirv.hpp>

#include "renderer/common/error.h"

namespace ds::spirv {

namespace {

constexpr size_t kHeaderWords = 5;

// One instruction: its opcode and operand words (the first word left out).
struct Instruction {
    spv::Op op;
    std::span<const uint32_t> operands;
    uint32_t operand(size_t i) const { return i < operands.size() ? operands[i] : 0; }
};

std::vector<Instruction> split(std::span<const uint32_t> spirv) {
    if (spirv.size() < kHeaderWords || spirv[0] != spv::MagicNumber)
        throw Error("SPIR-V: not a module (bad magic number or header)");
    std::vector<Instruction> out;
    for (size_t at = kHeaderWords; at < spirv.size();) {
        const uint32_t count = spirv[at] >> spv::WordCountShift;
        if (count == 0 || at + count > spirv.size())
            throw Error("SPIR-V: truncated instruction at word " + std::to_string(at));
        out.push_back({spv::Op(spirv[at] & spv::OpCodeMask), spirv.subspan(at + 1, count - 1)});
        at += count;
    }
    return out;
}

// Where a pointer comes from: its storage class (from its pointer type) and the value it was
// derived from (access chains, copies), so a store can be traced back to its variable.
struct Pointers {
    std::unordered_map<uint32_t, spv::StorageClass> type_class;  // OpTypePointer id
    std::unordered_map<uint32_t, uint32_t> type_pointee;         // OpTypePointer id
    std::unordered_map<uint32_t, uint32_t> result_type;          // pointer-valued results
    std::unordered_map<uint32_t, uint32_t> derived_from;         // access chain -> base
    std::unordered_set<uint32_t> variables;

    void note(const Instruction& in) {
        if (in.op == spv::OpTypePointer) {
            type_class[in.operand(0)] = spv::StorageClass(in.operand(1));
            type_pointee[in.operand(0)] = in.operand(2);
            return;
        }
        bool has_result = false, has_type = false;
        spv::HasResultAndType(in.op, &has_result, &has_type);
        if (!has_result || !has_type || !type_class.contains(in.operand(0))) return;
        result_type[in.operand(1)] = in.operand(0);
        if (in.op == spv::OpVariable) variables.insert(in.operand(1));
        if (in.op == spv::OpAccessChain || in.op == spv::OpInBoundsAccessChain ||
            in.op == spv::OpPtrAccessChain || in.op == spv::OpInBoundsPtrAccessChain ||
            in.op == spv::OpCopyObject)
            derived_from[in.operand(1)] = in.operand(2);
    }
    // The variable (or other root) a pointer was derived from.
    uint32_t root(uint32_t id) const {
        for (size_t guard = 0; guard < 1024; ++guard) {
            auto it = derived_from.find(id);
            if (it == derived_from.end()) break;
            id = it->second;
        }
        return id;
    }
    std::optional<spv::StorageClass> storage_class(uint32_t id) const {
        auto t = result_type.find(id);
        if (t == result_type.end()) return std::nullopt;
        return type_class.at(t->second);
    }
};

// Everything the second walk needs: decorations, entry point, pointers.
struct Module {
    std::vector<Instruction> code;
    Pointers pointers;
    std::unordered_map<uint32_t, spv::BuiltIn> builtins;  // variable -> BuiltIn decoration
    std::unordered_set<uint32_t> buffer_blocks;           // struct types decorated BufferBlock
    std::optional<uint32_t> fragment_entry;

    explicit Module(std::span<const uint32_t> spirv) : code(split(spirv)) {
        for (const Instruction& in : code) {
            if (in.op == spv::OpEntryPoint && in.operand(0) == spv::ExecutionModelFragment)
                fragment_entry = in.operand(1);
            if (in.op == spv::OpDecorate && in.operand(1) == spv::DecorationBuiltIn)
                builtins[in.operand(0)] = spv::BuiltIn(in.operand(2));
            if (in.op == spv::OpDecorate && in.operand(1) == spv::DecorationBufferBlock)
                buffer_blocks.insert(in.operand(0));
            pointers.note(in);
        }
        if (!fragment_entry) throw Error("SPIR-V: no Fragment entry point");
    }

    // Whether a write through `pointer` has side effects the depth test must not skip.
    bool is_storage(uint32_t pointer) const {
        const std::optional<spv::StorageClass> sc = pointers.storage_class(pointer);
        if (!sc) return false;
        if (*sc == spv::StorageClassStorageBuffer ||
            *sc == spv::StorageClassPhysicalStorageBuffer || *sc == spv::StorageClassImage)
            return true;
        if (*sc != spv::StorageClassUniform) return false;
        // Old-style storage buffers: Uniform whose block is decorated BufferBlock.
        const uint32_t var = pointers.root(pointer);
        const auto type = pointers.result_type.find(var);
        if (type == pointers.result_type.end()) return false;
        return buffer_blocks.contains(pointers.type_pointee.at(type->second));
    }
    bool is_builtin(uint32_t pointer, spv::BuiltIn builtin) const {
        auto it = builtins.find(pointers.root(pointer));
        return it != builtins.end() && it->second == builtin;
    }
};

void note_store(const Module& m, uint32_t pointer, FragmentFacts& f) {
    if (m.is_builtin(pointer, spv::BuiltInFragDepth)) f.writes_depth = true;
    if (m.is_builtin(pointer, spv::BuiltInSampleMask)) f.writes_sample_mask = true;
    if (m.is_storage(pointer)) f.storage_writes = true;
}

}  // namespace

std::optional<size_t> atomic_write_pointer(uint32_t opcode) {
    switch (spv::Op(opcode)) {
        case spv::OpAtomicStore:
        case spv::OpAtomicFlagClear:
            return 0;
        case spv::OpAtomicExchange:
        case spv::OpAtomicCompareExchange:
        case spv::OpAtomicCompareExchangeWeak:
        case spv::OpAtomicIIncrement:
        case spv::OpAtomicIDecrement:
        case spv::OpAtomicIAdd:
        case spv::OpAtomicISub:
        case spv::OpAtomicSMin:
        case spv::OpAtomicUMin:
        case spv::OpAtomicSMax:
        case spv::OpAtomicUMax:
        case spv::OpAtomicAnd:
        case spv::OpAtomicOr:
        case spv::OpAtomicXor:
        case spv::OpAtomicFlagTestAndSet:
        case spv::OpAtomicFMinEXT:
        case spv::OpAtomicFMaxEXT:
        case spv::OpAtomicFAddEXT:
            return 2;  // after result type and result
        default:
            return std::nullopt;
    }
}

FragmentFacts read_fragment_facts(std::span<const uint32_t> spirv) {
    const Module m(spirv);
    FragmentFacts f;
    for (const Instruction& in : m.code) {
        switch (in.op) {
            case spv::OpExecutionMode:
                if (in.operand(0) != *m.fragment_entry) break;
                if (in.operand(1) == spv::ExecutionModeEarlyFragmentTests)
                    f.early_fragment_tests = true;
                if (in.operand(1) == spv::ExecutionModeDepthReplacing) f.depth_replacing = true;
                break;
            case spv::OpKill:
            case spv::OpTerminateInvocation:
            case spv::OpDemoteToHelperInvocation:
                f.discards = true;
                break;
            case spv::OpImageWrite:
                f.storage_writes = true;
                break;
            case spv::OpStore:
            case spv::OpCopyMemory:
            case spv::OpCopyMemorySized:
                note_store(m, in.operand(0), f);
                break;
            default:
                if (const std::optional<size_t> p = atomic_write_pointer(in.op))
                    note_store(m, in.operand(*p), f);
        }
    }
    if (f.depth_replacing) f.writes_depth = true;
    return f;
}

std::string early_z_verdict(const FragmentFacts& f, bool alpha_to_coverage) {
    if (f.early_fragment_tests) return "guaranteed";
    const std::pair<bool, const char*> reasons[] = {{f.writes_depth, "depth write"},
                                                    {f.writes_sample_mask, "sample mask write"},
                                                    {f.discards, "discard"},
                                                    {f.storage_writes, "storage writes"},
                                                    {alpha_to_coverage, "alpha to coverage"}};
    std::string out;
    for (const auto& [lost, why] : reasons) {
        if (!lost) continue;
        out += out.empty() ? "lost: " : ", ";
        out += why;
    }
    return out.empty() ? "guaranteed" : out;
}

std::string early_z_verdict(std::span<const uint32_t> fragment, bool alpha_to_coverage) {
    if (fragment.empty()) return "guaranteed";
    return early_z_verdict(read_fragment_facts(fragment), alpha_to_coverage);
}

}  // namespace ds::spirv
