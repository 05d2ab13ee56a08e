#include "layer/spirv/instance_output.h"

#include <algorithm>
#include <string>

#include "layer/spirv/counters.h"
#include "layer/spirv/module.h"
#include "layer/spirv/module_index.h"
#include "renderer/common/error.h"

namespace ds::layer {

namespace {

constexpr uint32_t kMaxTypeDepth = 64;  // a deeper type graph is taken for a cycle

// The value of an array length: an OpConstant or an OpSpecConstant's default (low word).
uint32_t array_length(const ModuleIndex& s, uint32_t id) {
    const Instruction& c = def_of(s, id);
    if ((c.op != spv::OpConstant && c.op != spv::OpSpecConstant) || c.operands.size() < 3)
        throw Error("SPIR-V: an output array's length is not an OpConstant or OpSpecConstant");
    return c.operand(2);
}

// The locations a value of `type` takes (Vulkan spec, "Location Assignment").
uint32_t type_locations(const ModuleIndex& s, uint32_t type, uint32_t depth = 0) {
    if (depth > kMaxTypeDepth) throw Error("SPIR-V: an output's type contains itself");
    const Instruction& t = def_of(s, type);
    switch (t.op) {
        case spv::OpTypeBool:
        case spv::OpTypeInt:
        case spv::OpTypeFloat:
            return 1;
        case spv::OpTypeVector: {
            const Instruction& component = def_of(s, t.operand(1));
            return component.operand(1) == 64 && t.operand(2) > 2 ? 2 : 1;
        }
        case spv::OpTypeMatrix:
            return t.operand(2) * type_locations(s, t.operand(1), depth + 1);
        case spv::OpTypeArray:
            return array_length(s, t.operand(2)) * type_locations(s, t.operand(1), depth + 1);
        case spv::OpTypeStruct: {
            uint32_t sum = 0;
            for (size_t i = 1; i < t.operands.size(); ++i)
                sum += type_locations(s, t.operands[i], depth + 1);
            return sum;
        }
        default:
            throw Error("SPIR-V: an output's type (opcode " + std::to_string(t.op) +
                        ") has no location count");
    }
}

// OpDecorate `d`'s literal on `id`, if any.
bool decoration_value(const ModuleIndex& s, uint32_t id, spv::Decoration d, uint32_t& value) {
    for (const Instruction* in : decorations_of(s, id)) {
        if (in->op == spv::OpDecorate && in->operand(1) == uint32_t(d)) {
            value = in->operand(2);
            return true;
        }
    }
    return false;
}

// The first location after those `output` uses: from its Location, else from its (array of)
// block's member Locations, each element of an array taking the span of the members.
uint32_t output_end(const ModuleIndex& s, const Instruction& output) {
    const uint32_t pointee = def_of(s, output.operand(0)).operand(2);
    uint32_t location = 0;
    if (decoration_value(s, output.operand(1), spv::DecorationLocation, location))
        return location + type_locations(s, pointee);
    uint32_t elements = 1, type = pointee;
    for (uint32_t depth = 0; def_of(s, type).op == spv::OpTypeArray; ++depth) {
        if (depth > kMaxTypeDepth) throw Error("SPIR-V: an array type contains itself");
        elements *= array_length(s, def_of(s, type).operand(2));
        type = def_of(s, type).operand(1);
    }
    const Instruction& block = def_of(s, type);
    uint32_t first = UINT32_MAX, end = 0;
    for (const Instruction* d : decorations_of(s, type)) {
        if (block.op != spv::OpTypeStruct || d->op != spv::OpMemberDecorate ||
            d->operand(2) != spv::DecorationLocation || d->operand(1) + 1 >= block.operands.size())
            continue;
        first = std::min(first, d->operand(3));
        end = std::max(end, d->operand(3) + type_locations(s, block.operands[d->operand(1) + 1]));
    }
    if (first == UINT32_MAX) throw Error("SPIR-V: a vertex shader output has no Location");
    return first + elements * (end - first);
}

// The module's Input variable decorated BuiltIn InstanceIndex, and whether its type is signed;
// 0 when there is none.
uint32_t find_instance_index(const ModuleIndex& s, const Module& m, bool& is_signed) {
    for (const Instruction& in : m.section(Section::Global)) {
        if (in.op != spv::OpVariable || in.operand(2) != spv::StorageClassInput) continue;
        uint32_t builtin = 0;
        if (!decoration_value(s, in.operand(1), spv::DecorationBuiltIn, builtin) ||
            builtin != spv::BuiltInInstanceIndex)
            continue;
        const Instruction& type = def_of(s, def_of(s, in.operand(0)).operand(2));
        if (type.op != spv::OpTypeInt || type.operand(1) != 32)
            throw Error("SPIR-V: the InstanceIndex variable is not a 32-bit integer");
        is_signed = type.operand(2) != 0;
        return in.operand(1);
    }
    return 0;
}

uint32_t add_instance_index(Module& m) {
    const uint32_t int_type = m.type(spv::OpTypeInt, {32, 1});
    const uint32_t pointer = m.type(spv::OpTypePointer, {spv::StorageClassInput, int_type});
    const uint32_t id = m.new_id();
    m.add(Section::Global, spv::OpVariable, {pointer, id, spv::StorageClassInput});
    m.add(Section::Annotation, spv::OpDecorate,
          {id, spv::DecorationBuiltIn, spv::BuiltInInstanceIndex});
    add_name(m, id, "ds_InstanceIndex");
    return id;
}

}  // namespace

InstanceOutput add_instance_output(std::span<const uint32_t> vertex, std::string_view entry) {
    Module m(vertex);
    const size_t ep = find_entry_point(m, entry, {spv::ExecutionModelVertex});
    if (ep == SIZE_MAX)
        throw Error("SPIR-V: the module has no Vertex entry point named \"" + std::string(entry) +
                    "\"");
    InstanceOutput result;
    bool is_signed = true;
    uint32_t instance = 0;
    {
        const ModuleIndex s = index_module(m);  // points into m: used before m grows
        for (const Instruction* output : user_outputs(s, m.section(Section::EntryPoint)[ep]))
            result.location = std::max(result.location, output_end(s, *output));
        instance = find_instance_index(s, m, is_signed);
    }
    if (!instance) instance = add_instance_index(m);
    const uint32_t uint_type = m.type(spv::OpTypeInt, {32, 0});
    const uint32_t output = add_flat_uint(m, uint_type, spv::StorageClassOutput, result.location);

    // output = uint(gl_InstanceIndex) at the start of the entry's function.
    const uint32_t function = m.section(Section::EntryPoint)[ep].operand(1);
    std::vector<Instruction> code;
    Emitter e{m, code};
    const uint32_t value =
        e(spv::OpLoad, is_signed ? m.type(spv::OpTypeInt, {32, 1}) : uint_type, {instance});
    code.push_back(
        {spv::OpStore, {output, is_signed ? e(spv::OpBitcast, uint_type, {value}) : value}});
    std::vector<Instruction>& body = m.section(Section::Function);
    body.insert(body.begin() + std::ptrdiff_t(function_start(m, function)), code.begin(),
                code.end());

    Instruction& entry_point = m.section(Section::EntryPoint)[ep];
    add_to_interface(entry_point, instance);
    add_to_interface(entry_point, output);
    result.spirv = m.words();
    return result;
}

}  // namespace ds::layer
