#include "layer/spirv/survival_memory.h"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

#include "layer/spirv/counters.h"
#include "renderer/spirv/spirv_facts.h"

namespace ds::layer {

namespace {

// Decorations that only an interface variable has: they go with the Output class.
bool interface_decoration(uint32_t d) {
    switch (d) {
        case spv::DecorationLocation:
        case spv::DecorationComponent:
        case spv::DecorationIndex:
        case spv::DecorationBuiltIn:
        case spv::DecorationFlat:
        case spv::DecorationNoPerspective:
        case spv::DecorationCentroid:
        case spv::DecorationSample:
        case spv::DecorationPatch:
        case spv::DecorationInvariant:
        case spv::DecorationPerVertexKHR:
        case spv::DecorationPerPrimitiveEXT:
        case spv::DecorationXfbBuffer:
        case spv::DecorationXfbStride:
        case spv::DecorationOffset:
            return true;
        default:
            return false;
    }
}

// Execution modes that state how the shader writes depth or stencil: without the outputs they
// would be wrong.
bool output_execution_mode(uint32_t mode) {
    return mode == spv::ExecutionModeDepthReplacing || mode == spv::ExecutionModeDepthGreater ||
           mode == spv::ExecutionModeDepthLess || mode == spv::ExecutionModeDepthUnchanged ||
           mode == spv::ExecutionModeStencilRefReplacingEXT;
}

// Output variables and pointer types become Private; returns the variables.
std::unordered_set<uint32_t> privatize_outputs(Module& m) {
    std::unordered_set<uint32_t> variables;
    for (Instruction& in : m.section(Section::Global)) {
        if (in.op == spv::OpTypePointer && in.operand(1) == spv::StorageClassOutput)
            in.operands[1] = spv::StorageClassPrivate;
        if (in.op == spv::OpTypeForwardPointer && in.operand(1) == spv::StorageClassOutput)
            in.operands[1] = spv::StorageClassPrivate;
        if (in.op == spv::OpVariable && in.operand(2) == spv::StorageClassOutput) {
            in.operands[2] = spv::StorageClassPrivate;
            variables.insert(in.operand(1));
        }
    }
    return variables;
}

// The former outputs lose their interface decorations (and below SPIR-V 1.4 their place in
// the interfaces); the depth / stencil execution modes go.
void drop_output_interface(Module& m, const std::unordered_set<uint32_t>& outputs) {
    std::erase_if(m.section(Section::Annotation), [&](const Instruction& in) {
        return in.op == spv::OpDecorate && outputs.contains(in.operand(0)) &&
               interface_decoration(in.operand(1));
    });
    std::erase_if(m.section(Section::ExecutionMode), [](const Instruction& in) {
        return in.op == spv::OpExecutionMode && output_execution_mode(in.operand(1));
    });
    if (m.version() >= kSpirv14) return;
    for (Instruction& ep : m.section(Section::EntryPoint)) {
        const auto first = ep.operands.begin() + std::ptrdiff_t(interface_start(ep));
        ep.operands.erase(std::remove_if(first, ep.operands.end(),
                                         [&](uint32_t id) { return outputs.contains(id); }),
                          ep.operands.end());
    }
}

// A read-modify-write atomic (OpAtomicFlagTestAndSet has its own case).
bool atomic_read_modify_write(spv::Op op) { return spirv::atomic_write_pointer(op) == 2u; }

// The storage class of every pointer-typed result of the module.
class PointerClasses {
  public:
    explicit PointerClasses(const Module& m) {
        for (const Instruction& in : m.section(Section::Global))
            if (in.op == spv::OpTypePointer) type_class_[in.operand(0)] = in.operand(1);
        for (Section s : {Section::Global, Section::Function})
            for (const Instruction& in : m.section(s)) {
                bool has_result = false, has_type = false;
                spv::HasResultAndType(in.op, &has_result, &has_type);
                if (has_result && has_type) type_of_[in.operand(1)] = in.operand(0);
            }
    }
    // Whether a write through `pointer` stays in the invocation's (or its workgroup's) own
    // memory. A pointer of unknown class counts as memory.
    bool local(uint32_t pointer) const {
        const auto type = type_of_.find(pointer);
        if (type == type_of_.end()) return false;
        const auto c = type_class_.find(type->second);
        if (c == type_class_.end()) return false;
        return c->second == spv::StorageClassFunction || c->second == spv::StorageClassPrivate ||
               c->second == spv::StorageClassWorkgroup;
    }
    // The type `pointer` points to (0 if unknown), from its OpTypePointer.
    uint32_t pointee(const Module& m, uint32_t pointer) const {
        const auto type = type_of_.find(pointer);
        const Instruction* t = type == type_of_.end() ? nullptr : m.global(type->second);
        return t && t->op == spv::OpTypePointer ? t->operand(2) : 0;
    }

  private:
    std::unordered_map<uint32_t, uint32_t> type_of_, type_class_;
};

// Turns a module's writes into reads (or nothing).
class WriteRemover {
  public:
    explicit WriteRemover(Module& m) : m_(m), classes_(m) {}
    // Appends what `in` becomes to `out`.
    void rewrite(Instruction&& in, std::vector<Instruction>& out);

  private:
    uint32_t load_semantics(uint32_t semantics);
    uint32_t zero_of(uint32_t type);

    Module& m_;
    const PointerClasses classes_;
    std::unordered_map<uint32_t, uint32_t> semantics_, zeros_;  // original id -> new id
};

void WriteRemover::rewrite(Instruction&& in, std::vector<Instruction>& out) {
    switch (in.op) {
        case spv::OpStore:
        case spv::OpAtomicStore:
        case spv::OpCopyMemory:
        case spv::OpCopyMemorySized:
        case spv::OpAtomicFlagClear:
            if (!classes_.local(in.operand(0))) return;  // the target is operand 0
            break;
        case spv::OpImageWrite:
            return;
        case spv::OpAtomicFlagTestAndSet:
            if (classes_.local(in.operand(2))) break;
            {
                const uint32_t flag = classes_.pointee(m_, in.operand(2)), loaded = m_.new_id();
                out.push_back(
                    {spv::OpAtomicLoad,
                     {flag, loaded, in.operand(2), in.operand(3), load_semantics(in.operand(4))}});
                in = {spv::OpINotEqual, {in.operand(0), in.operand(1), loaded, zero_of(flag)}};
            }
            break;
        default:
            if (atomic_read_modify_write(in.op) && !classes_.local(in.operand(2)))
                in = {spv::OpAtomicLoad,
                      {in.operand(0), in.operand(1), in.operand(2), in.operand(3),
                       load_semantics(in.operand(4))}};
    }
    out.push_back(std::move(in));
}

// The semantics of a load in place of a write: Release and MakeAvailable dropped,
// AcquireRelease made Acquire. Relaxed when the semantics are not an OpConstant.
uint32_t WriteRemover::load_semantics(uint32_t semantics) {
    if (const auto it = semantics_.find(semantics); it != semantics_.end()) return it->second;
    const Instruction* c = m_.global(semantics);
    const uint32_t value = c && c->op == spv::OpConstant ? c->operand(2) : 0;
    uint32_t load =
        value & ~uint32_t(spv::MemorySemanticsReleaseMask | spv::MemorySemanticsAcquireReleaseMask |
                          spv::MemorySemanticsMakeAvailableMask);
    if (value & spv::MemorySemanticsAcquireReleaseMask) load |= spv::MemorySemanticsAcquireMask;
    const uint32_t id =
        c && load == value ? semantics : m_.constant(m_.type(spv::OpTypeInt, {32, 0}), load);
    return semantics_[semantics] = id;
}

uint32_t WriteRemover::zero_of(uint32_t type) {
    if (const auto it = zeros_.find(type); it != zeros_.end()) return it->second;
    const uint32_t id = m_.new_id();
    m_.add(Section::Global, spv::OpConstantNull, {type, id});
    return zeros_[type] = id;
}

}  // namespace

void remove_memory_effects(Module& m) {
    const std::unordered_set<uint32_t> outputs = privatize_outputs(m);
    drop_output_interface(m, outputs);
    WriteRemover remover(m);
    std::vector<Instruction> out;
    for (Instruction& in : m.section(Section::Function)) remover.rewrite(std::move(in), out);
    m.section(Section::Function) = std::move(out);
}

}  // namespace ds::layer
