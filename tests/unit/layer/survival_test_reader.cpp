#include "survival_test_reader.h"

#include <gtest/gtest.h>

#include <cstring>
#include <map>
#include <set>

#include "instrument_test_fixture.h"

namespace ds::layer::testing {

namespace {

bool read_modify_write(spv::Op op) {
    static const std::set<spv::Op> ops{spv::OpAtomicExchange,
                                       spv::OpAtomicCompareExchange,
                                       spv::OpAtomicCompareExchangeWeak,
                                       spv::OpAtomicIIncrement,
                                       spv::OpAtomicIDecrement,
                                       spv::OpAtomicIAdd,
                                       spv::OpAtomicISub,
                                       spv::OpAtomicSMin,
                                       spv::OpAtomicUMin,
                                       spv::OpAtomicSMax,
                                       spv::OpAtomicUMax,
                                       spv::OpAtomicAnd,
                                       spv::OpAtomicOr,
                                       spv::OpAtomicXor,
                                       spv::OpAtomicFAddEXT,
                                       spv::OpAtomicFMinEXT,
                                       spv::OpAtomicFMaxEXT,
                                       spv::OpAtomicFlagTestAndSet};
    return ops.contains(op);
}

bool terminator(spv::Op op) {
    return op == spv::OpBranch || op == spv::OpBranchConditional || op == spv::OpSwitch ||
           op == spv::OpReturn || op == spv::OpReturnValue || op == spv::OpKill ||
           op == spv::OpUnreachable || op == spv::OpTerminateInvocation;
}

// Whether an instruction whose first operand is a pointer type's id has that type as its
// result type (not a type declaration, decoration or name).
bool has_result_type(spv::Op op) {
    const bool type = op >= spv::OpTypeVoid && op <= spv::OpTypeForwardPointer;
    const bool annotation = op == spv::OpDecorate || op == spv::OpMemberDecorate ||
                            op == spv::OpDecorateId || op == spv::OpDecorateString ||
                            op == spv::OpMemberDecorateString || op == spv::OpName ||
                            op == spv::OpMemberName;
    return !type && !annotation;
}

// Pointers: their class, and the variable each derives from.
struct Pointers {
    std::map<uint32_t, uint32_t> type_class, type_of, base;  // base: access chain -> its base
    std::map<uint32_t, uint32_t> set, binding;               // variable -> decoration

    explicit Pointers(const std::vector<Op>& ops) {
        for (const Op& o : ops) {
            const auto& w = o.operands;
            if (o.op == spv::OpTypePointer) type_class[w[0]] = w[1];
            if (w.size() > 1 && type_class.contains(w[0]) && has_result_type(o.op))
                type_of[w[1]] = w[0];
            if (o.op == spv::OpAccessChain || o.op == spv::OpInBoundsAccessChain ||
                o.op == spv::OpPtrAccessChain || o.op == spv::OpImageTexelPointer)
                base[w[1]] = w[2];
            if (o.op == spv::OpDecorate && w[1] == spv::DecorationDescriptorSet) set[w[0]] = w[2];
            if (o.op == spv::OpDecorate && w[1] == spv::DecorationBinding) binding[w[0]] = w[2];
        }
    }
    uint32_t root(uint32_t id) const {
        for (auto it = base.find(id); it != base.end(); it = base.find(id)) id = it->second;
        return id;
    }
    bool in_buffer(uint32_t pointer, uint32_t s, uint32_t b) const {
        const uint32_t v = root(pointer);
        return set.contains(v) && set.at(v) == s && binding.contains(v) && binding.at(v) == b;
    }
    bool allowed(uint32_t pointer, uint32_t layer_set) const {
        const uint32_t v = root(pointer);
        if (set.contains(v) && set.at(v) == layer_set) return true;
        const auto type = type_of.find(pointer);
        if (type == type_of.end() || !type_class.contains(type->second)) return false;
        const uint32_t c = type_class.at(type->second);
        return c == spv::StorageClassFunction || c == spv::StorageClassPrivate ||
               c == spv::StorageClassWorkgroup;
    }
};

// The function id of Fragment entry point `entry`.
uint32_t entry_function(const std::vector<Op>& ops, const std::string& entry) {
    for (const Op& o : ops)
        if (o.op == spv::OpEntryPoint && o.operands[0] == spv::ExecutionModelFragment &&
            entry == reinterpret_cast<const char*>(o.operands.data() + 2))
            return o.operands[1];
    ADD_FAILURE() << "no Fragment entry point " << entry;
    return 0;
}

void read_globals(const std::vector<Op>& ops, uint32_t function, SurvivalFacts& f) {
    for (const Op& o : ops) {
        const auto& w = o.operands;
        f.output_variables += o.op == spv::OpVariable && w[2] == spv::StorageClassOutput;
        f.output_pointer_types += o.op == spv::OpTypePointer && w[1] == spv::StorageClassOutput;
        if (o.op != spv::OpExecutionMode) continue;
        f.early_fragment_tests |= w[0] == function && w[1] == spv::ExecutionModeEarlyFragmentTests;
        f.depth_modes +=
            w[1] == spv::ExecutionModeDepthReplacing || w[1] == spv::ExecutionModeDepthGreater ||
            w[1] == spv::ExecutionModeDepthLess || w[1] == spv::ExecutionModeDepthUnchanged ||
            w[1] == spv::ExecutionModeStencilRefReplacingEXT;
    }
}

}  // namespace

SurvivalFacts read_survival(std::span<const uint32_t> spirv, uint32_t set, uint32_t zpixel_binding,
                            uint32_t record_binding, const std::string& entry) {
    const std::vector<Op> ops = split(spirv);
    const Pointers p(ops);
    const uint32_t function = entry_function(ops, entry);
    SurvivalFacts f;
    read_globals(ops, function, f);
    bool in_entry = false;
    size_t umin = 0;
    spv::Op previous = spv::OpNop;
    bool previous_record = false;
    for (const Op& o : ops) {
        const auto& w = o.operands;
        if (o.op == spv::OpFunction) in_entry = w[1] == function;
        f.atomic_loads += o.op == spv::OpAtomicLoad;
        f.discards += o.op == spv::OpKill || o.op == spv::OpTerminateInvocation ||
                      o.op == spv::OpDemoteToHelperInvocation;
        if (o.op == spv::OpStore || o.op == spv::OpAtomicStore || o.op == spv::OpCopyMemory ||
            o.op == spv::OpCopyMemorySized || o.op == spv::OpAtomicFlagClear)
            f.foreign_writes += !p.allowed(w[0], set);
        if (read_modify_write(o.op)) f.foreign_writes += !p.allowed(w[2], set);
        f.foreign_writes += o.op == spv::OpImageWrite;
        umin += o.op == spv::OpAtomicUMin && p.in_buffer(w[2], set, zpixel_binding);
        if (terminator(o.op)) {
            const bool ret = in_entry && (o.op == spv::OpReturn || o.op == spv::OpReturnValue);
            if (ret) f.umin_per_return.push_back(umin);
            if (ret) f.returns_after_record += previous == spv::OpStore && previous_record;
            if (!ret) f.umin_elsewhere += umin;
            umin = 0;
        }
        previous = o.op;
        previous_record = o.op == spv::OpStore && p.in_buffer(w[0], set, record_binding);
    }
    return f;
}

size_t entry_returns(std::span<const uint32_t> spirv, const std::string& entry) {
    const std::vector<Op> ops = split(spirv);
    const uint32_t function = entry_function(ops, entry);
    bool in_entry = false;
    size_t n = 0;
    for (const Op& o : ops) {
        if (o.op == spv::OpFunction) in_entry = o.operands[1] == function;
        n += in_entry && (o.op == spv::OpReturn || o.op == spv::OpReturnValue);
    }
    return n;
}

}  // namespace ds::layer::testing
