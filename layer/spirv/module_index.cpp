#include "layer/spirv/module_index.h"

#include <algorithm>
#include <string>

#include "layer/spirv/counters.h"
#include "renderer/common/error.h"

namespace ds::layer {

ModuleIndex index_module(const Module& m) {
    ModuleIndex s;
    for (const Instruction& in : m.section(Section::Global)) {
        bool has_result = false, has_type = false;
        spv::HasResultAndType(in.op, &has_result, &has_type);
        if (has_result) s.defs[in.operand(has_type ? 1 : 0)] = &in;
    }
    for (const Instruction& in : m.section(Section::Annotation))
        if (in.op == spv::OpDecorate || in.op == spv::OpMemberDecorate)
            s.decorations[in.operand(0)].push_back(&in);
    return s;
}

const Instruction& def_of(const ModuleIndex& s, uint32_t id) {
    const auto it = s.defs.find(id);
    if (it == s.defs.end())
        throw Error("SPIR-V: id " + std::to_string(id) + " is not a type, constant or variable");
    return *it->second;
}

const std::vector<const Instruction*>& decorations_of(const ModuleIndex& s, uint32_t id) {
    static const std::vector<const Instruction*> none;
    const auto it = s.decorations.find(id);
    return it == s.decorations.end() ? none : it->second;
}

bool decorated(const ModuleIndex& s, uint32_t id, spv::Decoration d) {
    return std::any_of(decorations_of(s, id).begin(), decorations_of(s, id).end(),
                       [&](const Instruction* in) {
                           return in->op == spv::OpDecorate && in->operand(1) == uint32_t(d);
                       });
}

bool member_builtin(const ModuleIndex& s, uint32_t id) {
    return std::any_of(
        decorations_of(s, id).begin(), decorations_of(s, id).end(), [](const Instruction* in) {
            return in->op == spv::OpMemberDecorate && in->operand(2) == spv::DecorationBuiltIn;
        });
}

uint32_t element_type(const ModuleIndex& s, uint32_t type) {
    for (size_t depth = 0; def_of(s, type).op == spv::OpTypeArray; ++depth) {
        if (depth > 64) throw Error("SPIR-V: an array type contains itself");
        type = def_of(s, type).operand(1);
    }
    return type;
}

std::vector<const Instruction*> user_outputs(const ModuleIndex& s, const Instruction& ep) {
    std::vector<const Instruction*> out;
    for (size_t i = interface_start(ep); i < ep.operands.size(); ++i) {
        const Instruction& v = def_of(s, ep.operands[i]);
        if (v.op != spv::OpVariable)
            throw Error("SPIR-V: an entry point's interface lists a non-variable");
        if (v.operand(2) != spv::StorageClassOutput) continue;
        const Instruction& pointer = def_of(s, v.operand(0));
        if (pointer.op != spv::OpTypePointer)
            throw Error("SPIR-V: a variable's type is not a pointer");
        if (decorated(s, v.operand(1), spv::DecorationBuiltIn) ||
            member_builtin(s, element_type(s, pointer.operand(2))))
            continue;
        out.push_back(&v);
    }
    return out;
}

}  // namespace ds::layer
