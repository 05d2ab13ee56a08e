#include "layer/spirv/instrument.h"

#include <algorithm>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "layer/spirv/module.h"
#include "renderer/common/error.h"
#include "renderer/spirv/spirv_facts.h"

namespace ds::layer {

namespace {

constexpr uint32_t kSpirv13 = 0x00010300;
constexpr uint32_t kSpirv14 = 0x00010400;
constexpr const char* kStorageBufferExtension = "SPV_KHR_storage_buffer_storage_class";

// Counter slots: DrawCounters member and the pixel's counts[] offset alike.
constexpr uint32_t kShaded = 0;
constexpr uint32_t kDiscarded = 1;

bool is_discard(spv::Op op) {
    // OpDemoteToHelperInvocationEXT has the same opcode as OpDemoteToHelperInvocation.
    return op == spv::OpKill || op == spv::OpTerminateInvocation ||
           op == spv::OpDemoteToHelperInvocation;
}

// Where the interface ids of an OpEntryPoint start (after model, function and name).
size_t interface_start(const Instruction& ep) {
    if (ep.operands.size() < 3) throw Error("SPIR-V: an OpEntryPoint has no name");
    size_t used = 0;
    read_string(std::span(ep.operands).subspan(2), &used);
    return 2 + used;
}

void add_to_interface(Instruction& ep, uint32_t id) {
    const auto first = ep.operands.begin() + std::ptrdiff_t(interface_start(ep));
    if (std::find(first, ep.operands.end(), id) == ep.operands.end()) ep.operands.push_back(id);
}

size_t find_entry(const Module& m, std::string_view name) {
    const std::vector<Instruction>& eps = m.section(Section::EntryPoint);
    for (size_t i = 0; i < eps.size(); ++i) {
        if (eps[i].operand(0) != spv::ExecutionModelFragment) continue;
        interface_start(eps[i]);  // checks the name is there and terminated
        if (read_string(std::span(eps[i].operands).subspan(2)) == name) return i;
    }
    throw Error("SPIR-V: the module has no Fragment entry point named \"" + std::string(name) +
                "\"");
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

bool has_extension(const Module& m, std::string_view name) {
    for (const Instruction& in : m.section(Section::Extension))
        if (read_string(in.operands) == name) return true;
    return false;
}

bool vulkan_memory_model(const Module& m) {
    const std::vector<Instruction>& mm = m.section(Section::MemoryModel);
    return !mm.empty() && mm.front().operand(1) == spv::MemoryModelVulkan;
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

// The ids the counting code uses.
struct Counters {
    uint32_t uint_type = 0, bool_type = 0, float_type = 0, vec4_type = 0;
    uint32_t frag_coord = 0;  // Input variable, BuiltIn FragCoord
    uint32_t draw = 0, pixel = 0, uint_pointer = 0;
    uint32_t zero = 0, one = 0, four = 0, scope = 0;
};

void name(Module& m, uint32_t id, std::string_view text) {
    std::vector<uint32_t> operands = string_words(text);
    operands.insert(operands.begin(), id);
    m.add(Section::DebugName, spv::OpName, std::move(operands));
}

// The module's Input variable decorated BuiltIn FragCoord (its vec4 and float types too).
bool find_frag_coord(const Module& m, Counters& c) {
    std::unordered_set<uint32_t> decorated;
    for (const Instruction& in : m.section(Section::Annotation))
        if (in.op == spv::OpDecorate && in.operand(1) == spv::DecorationBuiltIn &&
            in.operand(2) == spv::BuiltInFragCoord)
            decorated.insert(in.operand(0));
    for (const Instruction& in : m.section(Section::Global)) {
        if (in.op != spv::OpVariable || in.operand(2) != spv::StorageClassInput ||
            !decorated.contains(in.operand(1)))
            continue;
        const Instruction* pointer = m.global(in.operand(0));
        const Instruction* vec = pointer ? m.global(pointer->operand(2)) : nullptr;
        if (!vec || vec->op != spv::OpTypeVector)
            throw Error("SPIR-V: the FragCoord variable is not a vector");
        c.frag_coord = in.operand(1);
        c.vec4_type = vec->operand(0);
        c.float_type = vec->operand(1);
        return true;
    }
    return false;
}

void add_frag_coord(Module& m, Counters& c) {
    c.float_type = m.type(spv::OpTypeFloat, {32});
    c.vec4_type = m.type(spv::OpTypeVector, {c.float_type, 4});
    const uint32_t pointer = m.new_id();
    m.add(Section::Global, spv::OpTypePointer, {pointer, spv::StorageClassInput, c.vec4_type});
    c.frag_coord = m.new_id();
    m.add(Section::Global, spv::OpVariable, {pointer, c.frag_coord, spv::StorageClassInput});
    m.add(Section::Annotation, spv::OpDecorate,
          {c.frag_coord, spv::DecorationBuiltIn, spv::BuiltInFragCoord});
    name(m, c.frag_coord, "ds_FragCoord");
}

// A Block struct of `members` uints (and a trailing runtime array of them when `runtime` is
// set), std430 offsets, in a StorageBuffer variable at (set, binding). Returns the variable.
uint32_t add_buffer(Module& m, const Counters& c, std::string_view type_name, uint32_t set,
                    uint32_t binding, uint32_t runtime_array) {
    const uint32_t block = m.new_id();
    std::vector<uint32_t> members{block, c.uint_type, c.uint_type, c.uint_type, c.uint_type};
    if (runtime_array) members.push_back(runtime_array);
    m.add(Section::Global, spv::OpTypeStruct, members);
    m.add(Section::Annotation, spv::OpDecorate, {block, spv::DecorationBlock});
    for (uint32_t i = 0; i + 1 < members.size(); ++i)
        m.add(Section::Annotation, spv::OpMemberDecorate, {block, i, spv::DecorationOffset, 4 * i});
    name(m, block, type_name);

    const uint32_t pointer = m.new_id();
    m.add(Section::Global, spv::OpTypePointer, {pointer, spv::StorageClassStorageBuffer, block});
    const uint32_t variable = m.new_id();
    m.add(Section::Global, spv::OpVariable, {pointer, variable, spv::StorageClassStorageBuffer});
    m.add(Section::Annotation, spv::OpDecorate, {variable, spv::DecorationDescriptorSet, set});
    m.add(Section::Annotation, spv::OpDecorate, {variable, spv::DecorationBinding, binding});
    name(m, variable, std::string("ds_") + std::string(type_name));
    return variable;
}

// Every global the counting code needs: types (reused when present), constants, FragCoord, the
// two buffers, the extension SPIR-V < 1.3 needs for the StorageBuffer storage class.
Counters add_globals(Module& m, const CounterBindings& b) {
    Counters c;
    c.uint_type = m.type(spv::OpTypeInt, {32, 0});
    c.bool_type = m.type(spv::OpTypeBool, {});
    if (!find_frag_coord(m, c)) add_frag_coord(m, c);
    c.zero = m.constant(c.uint_type, 0);
    c.one = m.constant(c.uint_type, 1);
    c.four = m.constant(c.uint_type, 4);
    c.scope = vulkan_memory_model(m) ? m.constant(c.uint_type, spv::ScopeQueueFamily)
                                     : m.constant(c.uint_type, spv::ScopeDevice);

    const uint32_t counts = m.new_id();
    m.add(Section::Global, spv::OpTypeRuntimeArray, {counts, c.uint_type});
    m.add(Section::Annotation, spv::OpDecorate, {counts, spv::DecorationArrayStride, 4});
    c.draw = add_buffer(m, c, "DrawCounters", b.set, b.draw_binding, 0);
    c.pixel = add_buffer(m, c, "PixelCounters", b.set, b.pixel_binding, counts);
    c.uint_pointer = m.new_id();
    m.add(Section::Global, spv::OpTypePointer,
          {c.uint_pointer, spv::StorageClassStorageBuffer, c.uint_type});

    if (m.version() < kSpirv13 && !has_extension(m, kStorageBufferExtension))
        m.add(Section::Extension, spv::OpExtension, string_words(kStorageBufferExtension));
    return c;
}

// Appends instructions with a result to a block of function code.
struct Emitter {
    Module& m;
    std::vector<Instruction>& out;

    uint32_t operator()(spv::Op op, uint32_t type, std::vector<uint32_t> operands) {
        const uint32_t id = m.new_id();
        operands.insert(operands.begin(), {type, id});
        out.push_back({op, std::move(operands)});
        return id;
    }
};

// DrawCounters[slot] += 1; counts[(y * width + x) * 4 + slot] += 1 inside width x height, else
// counts[0] += 0 (no branch: the block stays whole).
void emit_count(Module& m, const Counters& c, uint32_t slot, std::vector<Instruction>& out) {
    Emitter e{m, out};
    const uint32_t u = c.uint_type, b = c.bool_type, ptr = c.uint_pointer;
    const uint32_t k = slot == kShaded ? c.zero : c.one;
    const uint32_t coord = e(spv::OpLoad, c.vec4_type, {c.frag_coord});
    const uint32_t x =
        e(spv::OpConvertFToU, u, {e(spv::OpCompositeExtract, c.float_type, {coord, 0})});
    const uint32_t y =
        e(spv::OpConvertFToU, u, {e(spv::OpCompositeExtract, c.float_type, {coord, 1})});
    const uint32_t width = e(spv::OpLoad, u, {e(spv::OpAccessChain, ptr, {c.pixel, c.zero})});
    const uint32_t height = e(spv::OpLoad, u, {e(spv::OpAccessChain, ptr, {c.pixel, c.one})});
    const uint32_t inside_x = e(spv::OpULessThan, b, {x, width});
    const uint32_t inside_y = e(spv::OpULessThan, b, {y, height});
    const uint32_t inside = e(spv::OpLogicalAnd, b, {inside_x, inside_y});
    const uint32_t row = e(spv::OpIMul, u, {y, width});
    const uint32_t pixel = e(spv::OpIAdd, u, {row, x});
    const uint32_t first = e(spv::OpIMul, u, {pixel, c.four});
    const uint32_t index = e(spv::OpSelect, u, {inside, e(spv::OpIAdd, u, {first, k}), c.zero});
    const uint32_t amount = e(spv::OpSelect, u, {inside, c.one, c.zero});
    const uint32_t count = e(spv::OpAccessChain, ptr, {c.pixel, c.four, index});
    e(spv::OpAtomicIAdd, u, {count, c.scope, c.zero, amount});
    const uint32_t draw = e(spv::OpAccessChain, ptr, {c.draw, k});
    e(spv::OpAtomicIAdd, u, {draw, c.scope, c.zero, c.one});
}

// The ids of the module's non-semantic extended instruction sets (their OpExtInst may sit
// among a function's OpVariables).
std::unordered_set<uint32_t> non_semantic_sets(const Module& m) {
    std::unordered_set<uint32_t> out;
    for (const Instruction& in : m.section(Section::ExtInstImport))
        if (read_string(std::span(in.operands).subspan(1)).starts_with("NonSemantic."))
            out.insert(in.operand(0));
    return out;
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
    auto leads_block = [&](const Instruction& in) {
        return in.op == spv::OpVariable || in.op == spv::OpLine || in.op == spv::OpNoLine ||
               (in.op == spv::OpExtInst && debug_sets.contains(in.operand(2)));
    };
    enum class Start { Before, AwaitLabel, InFirstBlock, Done } start = Start::Before;
    Walk walk;
    uint32_t function = 0;
    std::vector<Instruction> out;
    for (Instruction& in : m.section(Section::Function)) {
        if (start == Start::InFirstBlock && !leads_block(in)) {
            emit_count(m, c, kShaded, out);
            start = Start::Done;
        }
        if (is_discard(in.op)) {
            emit_count(m, c, kDiscarded, out);
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
                                     const CounterBindings& b) {
    Module m(spirv);
    const size_t entry_index = find_entry(m, entry);
    const uint32_t entry_fn = m.section(Section::EntryPoint)[entry_index].operand(1);
    check_bindings(m, b);

    InstrumentResult result;
    result.early_fragment_tests_added = may_add_early_tests(m, entry_fn, spirv);
    const Counters c = add_globals(m, b);
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
