#include "layer/spirv/counters.h"

#include <algorithm>
#include <string>
#include <unordered_set>

#include "renderer/common/error.h"

namespace ds::layer {

namespace {

constexpr const char* kStorageBufferExtension = "SPV_KHR_storage_buffer_storage_class";

bool vulkan_memory_model(const Module& m) {
    const std::vector<Instruction>& mm = m.section(Section::MemoryModel);
    return !mm.empty() && mm.front().operand(1) == spv::MemoryModelVulkan;
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
    add_name(m, c.frag_coord, "ds_FragCoord");
}

}  // namespace

uint32_t add_buffer(Module& m, const Counters& c, std::string_view type_name, uint32_t set,
                    uint32_t binding, uint32_t runtime_array) {
    const uint32_t block = m.new_id();
    std::vector<uint32_t> members{block, c.uint_type, c.uint_type, c.uint_type, c.uint_type};
    if (runtime_array) members.push_back(runtime_array);
    m.add(Section::Global, spv::OpTypeStruct, members);
    m.add(Section::Annotation, spv::OpDecorate, {block, spv::DecorationBlock});
    for (uint32_t i = 0; i + 1 < members.size(); ++i)
        m.add(Section::Annotation, spv::OpMemberDecorate, {block, i, spv::DecorationOffset, 4 * i});
    add_name(m, block, type_name);

    const uint32_t pointer = m.new_id();
    m.add(Section::Global, spv::OpTypePointer, {pointer, spv::StorageClassStorageBuffer, block});
    const uint32_t variable = m.new_id();
    m.add(Section::Global, spv::OpVariable, {pointer, variable, spv::StorageClassStorageBuffer});
    m.add(Section::Annotation, spv::OpDecorate, {variable, spv::DecorationDescriptorSet, set});
    m.add(Section::Annotation, spv::OpDecorate, {variable, spv::DecorationBinding, binding});
    add_name(m, variable, std::string("ds_") + std::string(type_name));
    return variable;
}

void add_name(Module& m, uint32_t id, std::string_view text) {
    std::vector<uint32_t> operands = string_words(text);
    operands.insert(operands.begin(), id);
    m.add(Section::DebugName, spv::OpName, std::move(operands));
}

bool has_extension(const Module& m, std::string_view name) {
    for (const Instruction& in : m.section(Section::Extension))
        if (read_string(in.operands) == name) return true;
    return false;
}

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

size_t find_entry_point(const Module& m, std::string_view name,
                        std::initializer_list<spv::ExecutionModel> models) {
    const std::vector<Instruction>& eps = m.section(Section::EntryPoint);
    for (size_t i = 0; i < eps.size(); ++i) {
        if (std::find(models.begin(), models.end(), spv::ExecutionModel(eps[i].operand(0))) ==
            models.end())
            continue;
        interface_start(eps[i]);  // checks the name is there and terminated
        if (read_string(std::span(eps[i].operands).subspan(2)) == name) return i;
    }
    return SIZE_MAX;
}

Counters add_common_globals(Module& m) {
    Counters c;
    c.uint_type = m.type(spv::OpTypeInt, {32, 0});
    c.bool_type = m.type(spv::OpTypeBool, {});
    if (!find_frag_coord(m, c)) add_frag_coord(m, c);
    c.zero = m.constant(c.uint_type, 0);
    c.one = m.constant(c.uint_type, 1);
    c.four = m.constant(c.uint_type, 4);
    c.scope = vulkan_memory_model(m) ? m.constant(c.uint_type, spv::ScopeQueueFamily)
                                     : m.constant(c.uint_type, spv::ScopeDevice);
    return c;
}

uint32_t add_uint_runtime_array(Module& m, uint32_t uint_type) {
    const uint32_t id = m.new_id();
    m.add(Section::Global, spv::OpTypeRuntimeArray, {id, uint_type});
    m.add(Section::Annotation, spv::OpDecorate, {id, spv::DecorationArrayStride, 4});
    return id;
}

void require_storage_buffer_class(Module& m) {
    if (m.version() < kSpirv13 && !has_extension(m, kStorageBufferExtension))
        m.add(Section::Extension, spv::OpExtension, string_words(kStorageBufferExtension));
}

Counters add_counter_globals(Module& m, const CounterBindings& b) {
    Counters c = add_common_globals(m);
    const uint32_t counts = add_uint_runtime_array(m, c.uint_type);
    c.draw = add_buffer(m, c, "DrawCounters", b.set, b.draw_binding, 0);
    c.pixel = add_buffer(m, c, "PixelCounters", b.set, b.pixel_binding, counts);
    c.uint_pointer = m.new_id();
    m.add(Section::Global, spv::OpTypePointer,
          {c.uint_pointer, spv::StorageClassStorageBuffer, c.uint_type});
    require_storage_buffer_class(m);
    return c;
}

std::unordered_set<uint32_t> non_semantic_sets(const Module& m) {
    std::unordered_set<uint32_t> out;
    for (const Instruction& in : m.section(Section::ExtInstImport))
        if (read_string(std::span(in.operands).subspan(1)).starts_with("NonSemantic."))
            out.insert(in.operand(0));
    return out;
}

bool leads_first_block(const Instruction& in, const std::unordered_set<uint32_t>& debug_sets) {
    return in.op == spv::OpVariable || in.op == spv::OpLine || in.op == spv::OpNoLine ||
           (in.op == spv::OpExtInst && debug_sets.contains(in.operand(2)));
}

size_t function_start(const Module& m, uint32_t function) {
    const std::unordered_set<uint32_t> debug_sets = non_semantic_sets(m);
    const std::vector<Instruction>& code = m.section(Section::Function);
    size_t i = 0;
    while (i < code.size() && !(code[i].op == spv::OpFunction && code[i].operand(1) == function))
        ++i;
    while (i < code.size() && code[i].op != spv::OpLabel && code[i].op != spv::OpFunctionEnd) ++i;
    if (i == code.size() || code[i].op != spv::OpLabel)
        throw Error("SPIR-V: the entry point's function has no body in the module");
    for (++i; i < code.size() && leads_first_block(code[i], debug_sets);) ++i;
    return i;
}

void emit_count(Module& m, const Counters& c, uint32_t slot, std::vector<Instruction>& out) {
    Emitter e{m, out};
    const uint32_t u = c.uint_type, b = c.bool_type, ptr = c.uint_pointer;
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
    const uint32_t index = e(spv::OpSelect, u, {inside, e(spv::OpIAdd, u, {first, slot}), c.zero});
    const uint32_t amount = e(spv::OpSelect, u, {inside, c.one, c.zero});
    const uint32_t count = e(spv::OpAccessChain, ptr, {c.pixel, c.four, index});
    e(spv::OpAtomicIAdd, u, {count, c.scope, c.zero, amount});
    const uint32_t draw = e(spv::OpAccessChain, ptr, {c.draw, slot});
    e(spv::OpAtomicIAdd, u, {draw, c.scope, c.zero, c.one});
}

uint32_t add_flat_uint(Module& m, uint32_t uint_type, spv::StorageClass storage,
                       uint32_t location) {
    const uint32_t pointer = m.type(spv::OpTypePointer, {uint32_t(storage), uint_type});
    const uint32_t id = m.new_id();
    m.add(Section::Global, spv::OpVariable, {pointer, id, uint32_t(storage)});
    m.add(Section::Annotation, spv::OpDecorate, {id, spv::DecorationLocation, location});
    m.add(Section::Annotation, spv::OpDecorate, {id, spv::DecorationFlat});
    add_name(m, id, "ds_instance");
    return id;
}

}  // namespace ds::layer
