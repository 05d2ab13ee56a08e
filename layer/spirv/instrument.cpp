#include "layer/spirv/instrument.h"

#include <algorithm>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "layer/spirv/counters.h"
#include "layer/spirv/module.h"
#include "renderer/common/error.h"
#include "renderer/spirv/spirv_facts.h"

namespace ds::layer {

namespace {

bool is_discard(spv::Op op) {
    // OpDemoteToHelperInvocationEXT has the same opcode as OpDemoteToHelperInvocation.
    return op == spv::OpKill || op == spv::OpTerminateInvocation ||
           op == spv::OpDemoteToHelperInvocation;
}

size_t find_entry(const Module& m, std::string_view name) {
    const size_t i = find_entry_point(m, name, {spv::ExecutionModelFragment});
    if (i == SIZE_MAX)
        throw Error("SPIR-V: the module has no Fragment entry point named \"" + std::string(name) +
                    "\"");
    return i;
}

void check_bindings(const Module& m, const CounterBindings& b) {
    if (b.draw_binding == b.pixel_binding)
        throw Error("SPIR-V instrument: the draw and pixel counters need different bindings");
    for (const Instruction& in : m.section(Section::Annotation)) {
        if (in.op == spv::OpDecorate && in.operand(1) == spv::DecorationDescriptorSet &&
            in.operand(2) == b.set)
            throw Error("SPIR-V: the module already uses descriptor set " + std::to_string(b.set) +
                        ", the set the counters need");
    }
}

// Execution modes after which EarlyFragmentTests would change what the shader does (or that
// state the application's own choice of when to test).
bool blocks_early_tests(uint32_t mode) {
    switch (mode) {
        case spv::ExecutionModeEarlyFragmentTests:
        case spv::ExecutionModeDepthReplacing:
        case spv::ExecutionModeDepthGreater:
        case spv::ExecutionModeDepthLess:
        case spv::ExecutionModeDepthUnchanged:
        case spv::ExecutionModeStencilRefReplacingEXT:
        case spv::ExecutionModeEarlyAndLateFragmentTestsAMD:
            return true;
        default:
            return false;
    }
}

// Whether EarlyFragmentTests keeps the application's behaviour: nothing the tests' timing
// could change (the facts are the module's, so any entry's discard or write counts) and the
// entry does not choose already.
bool may_add_early_tests(const Module& m, uint32_t entry_fn, std::span<const uint32_t> original) {
    const spirv::FragmentFacts f = spirv::read_fragment_facts(original);
    if (f.discards || f.writes_depth || f.writes_sample_mask || f.storage_writes) return false;
    for (const Instruction& in : m.section(Section::ExecutionMode))
        if (in.op == spv::OpExecutionMode && in.operand(0) == entry_fn &&
            blocks_early_tests(in.operand(1)))
            return false;
    return true;
}

// What the walk over the functions found.
struct Walk {
    uint32_t discard_sites = 0;
    std::unordered_set<uint32_t> discarding;                           // functions
    std::unordered_map<uint32_t, std::unordered_set<uint32_t>> calls;  // caller -> callees
};

// Inserts the counting code into the functions: the shaded count at the start of the entry
// function (after its first block's OpVariables and the debug instructions among them), the
// discarded count before every discard of any function.
Walk instrument_functions(Module& m, const Counters& c, uint32_t entry_fn) {
    const std::unordered_set<uint32_t> debug_sets = non_semantic_sets(m);
    enum class Start { Before, AwaitLabel, InFirstBlock, Done } start = Start::Before;
    Walk walk;
    uint32_t function = 0;
    std::vector<Instruction> out;
    for (Instruction& in : m.section(Section::Function)) {
        if (start == Start::InFirstBlock && !leads_first_block(in, debug_sets)) {
            emit_count(m, c, c.zero, out);  // slot 0: shaded
            start = Start::Done;
        }
        if (is_discard(in.op)) {
            emit_count(m, c, c.one, out);  // slot 1: discarded
            ++walk.discard_sites;
            walk.discarding.insert(function);
        }
        if (in.op == spv::OpFunction) function = in.operand(1);
        if (in.op == spv::OpFunction && function == entry_fn) start = Start::AwaitLabel;
        if (in.op == spv::OpFunctionCall) walk.calls[function].insert(in.operand(2));
        if (in.op == spv::OpLabel && start == Start::AwaitLabel) start = Start::InFirstBlock;
        out.push_back(std::move(in));
    }
    if (start != Start::Done)
        throw Error("SPIR-V: the entry point's function has no body in the module");
    m.section(Section::Function) = std::move(out);
    return walk;
}

// Whether `function` or a function it calls (at any depth) discards.
bool reaches_discard(const Walk& walk, uint32_t function) {
    std::unordered_set<uint32_t> seen{function};
    std::vector<uint32_t> todo{function};
    while (!todo.empty()) {
        const uint32_t f = todo.back();
        todo.pop_back();
        if (walk.discarding.contains(f)) return true;
        const auto callees = walk.calls.find(f);
        if (callees == walk.calls.end()) continue;
        for (uint32_t callee : callees->second)
            if (seen.insert(callee).second) todo.push_back(callee);
    }
    return false;
}

// FragCoord (an Input) joins the interface of every Fragment entry point that now uses it; the
// buffers too from SPIR-V 1.4 on, where the interface lists every global an entry uses.
void update_interfaces(Module& m, size_t entry, const Counters& c, const Walk& walk) {
    std::vector<uint32_t> ids{c.frag_coord};
    if (m.version() >= kSpirv14) ids.insert(ids.end(), {c.draw, c.pixel});
    std::vector<Instruction>& eps = m.section(Section::EntryPoint);
    for (size_t i = 0; i < eps.size(); ++i) {
        const bool uses = i == entry || (eps[i].operand(0) == spv::ExecutionModelFragment &&
                                         reaches_discard(walk, eps[i].operand(1)));
        if (!uses) continue;
        for (uint32_t id : ids) add_to_interface(eps[i], id);
    }
}

}  // namespace

InstrumentResult instrument_fragment(std::span<const uint32_t> spirv, std::string_view entry,
                                     const CounterBindings& b, bool alpha_to_coverage) {
    Module m(spirv);
    const size_t entry_index = find_entry(m, entry);
    const uint32_t entry_fn = m.section(Section::EntryPoint)[entry_index].operand(1);
    check_bindings(m, b);

    InstrumentResult result;
    result.early_fragment_tests_added =
        !alpha_to_coverage && may_add_early_tests(m, entry_fn, spirv);
    const Counters c = add_counter_globals(m, b);
    const Walk walk = instrument_functions(m, c, entry_fn);
    update_interfaces(m, entry_index, c, walk);
    if (result.early_fragment_tests_added)
        m.add(Section::ExecutionMode, spv::OpExecutionMode,
              {entry_fn, spv::ExecutionModeEarlyFragmentTests});
    result.discard_sites = walk.discard_sites;
    result.spirv = m.words();
    return result;
}

}  // namespace ds::layer
