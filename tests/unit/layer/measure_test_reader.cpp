#include "measure_test_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "instrument_test_fixture.h"

namespace ds::layer::testing {

InterfaceReader::InterfaceReader(std::span<const uint32_t> spirv) {
    for (const Op& o : split(spirv)) {
        const std::vector<uint32_t> w(o.operands.begin(), o.operands.end());
        switch (o.op) {
            case spv::OpTypeBool:
            case spv::OpTypeInt:
            case spv::OpTypeFloat:
            case spv::OpTypeVector:
            case spv::OpTypeMatrix:
            case spv::OpTypeArray:
            case spv::OpTypeRuntimeArray:
            case spv::OpTypeStruct:
            case spv::OpTypePointer:
                defs_[w[0]] = {o.op, {w.begin() + 1, w.end()}};
                break;
            case spv::OpConstant:
            case spv::OpSpecConstant:
            case spv::OpVariable:
                defs_[w[1]] = {o.op, {w[0]}};
                defs_[w[1]].operands.insert(defs_[w[1]].operands.end(), w.begin() + 2, w.end());
                break;
            case spv::OpDecorate:
                decorations_[w[0]].push_back({UINT32_MAX, w[1], w.size() > 2 ? w[2] : 0});
                break;
            case spv::OpMemberDecorate:
                decorations_[w[0]].push_back({w[1], w[2], w.size() > 3 ? w[3] : 0});
                break;
            case spv::OpEntryPoint: {
                const size_t name_words = std::strlen(reinterpret_cast<const char*>(&w[2])) / 4 + 1;
                entries_.push_back({w[0], {w.begin() + 2 + std::ptrdiff_t(name_words), w.end()}});
                break;
            }
            case spv::OpCapability:
                capabilities_.push_back(w[0]);
                break;
            default:
                break;
        }
    }
}

const InterfaceReader::Def& InterfaceReader::def(uint32_t id) const {
    static const Def none{spv::OpNop, {0, 0, 0}};
    const auto it = defs_.find(id);
    if (it != defs_.end()) return it->second;
    ADD_FAILURE() << "id " << id << " is not defined";
    return none;
}

bool InterfaceReader::has(uint32_t id, uint32_t member, spv::Decoration d, uint32_t* value) const {
    const auto it = decorations_.find(id);
    if (it == decorations_.end()) return false;
    for (const Decoration& x : it->second) {
        if (x.member != member || x.decoration != uint32_t(d)) continue;
        if (value) *value = x.value;
        return true;
    }
    return false;
}

uint32_t InterfaceReader::element(uint32_t type) const {
    while (def(type).op == spv::OpTypeArray) type = def(type).operands[0];
    return type;
}

std::string InterfaceReader::describe(uint32_t type) const {
    const Def& t = def(type);
    const auto& w = t.operands;
    switch (t.op) {
        case spv::OpTypeBool:
            return "bool";
        case spv::OpTypeInt:
            return (w[1] ? "i" : "u") + std::to_string(w[0]);
        case spv::OpTypeFloat:
            return "f" + std::to_string(w[0]);
        case spv::OpTypeVector:
        case spv::OpTypeMatrix:
            return (t.op == spv::OpTypeVector ? "v" : "m") + std::to_string(w[1]) + "<" +
                   describe(w[0]) + ">";
        case spv::OpTypeArray: {
            const Def& length = def(w[1]);
            uint32_t spec = 0;
            const std::string prefix = has(w[1], UINT32_MAX, spv::DecorationSpecId, &spec)
                                           ? "spec" + std::to_string(spec) + "="
                                           : "";
            return "[" + prefix + std::to_string(length.operands[1]) + "]" + describe(w[0]);
        }
        case spv::OpTypeStruct: {
            std::string out = has(type, UINT32_MAX, spv::DecorationBlock) ? "block{" : "struct{";
            for (uint32_t i = 0; i < w.size(); ++i) {
                uint32_t location = 0, component = 0;
                out += describe(w[i]);
                if (has(type, i, spv::DecorationLocation, &location))
                    out += " @" + std::to_string(location);
                if (has(type, i, spv::DecorationComponent, &component))
                    out += "." + std::to_string(component);
                out += ";";
            }
            return out + "}";
        }
        default:
            return "op" + std::to_string(t.op);
    }
}

bool InterfaceReader::flat_ok(uint32_t type, bool flat) const {
    const Def& t = def(type);
    switch (t.op) {
        case spv::OpTypeBool:
        case spv::OpTypeInt:
            return flat;
        case spv::OpTypeFloat:
            return flat || t.operands[0] != 64;
        case spv::OpTypeVector:
        case spv::OpTypeMatrix:
        case spv::OpTypeArray:
            return flat_ok(t.operands[0], flat);
        case spv::OpTypeStruct:
            for (uint32_t i = 0; i < t.operands.size(); ++i)
                if (!flat_ok(t.operands[i], flat || has(type, i, spv::DecorationFlat)))
                    return false;
            return true;
        default:
            return true;
    }
}

std::map<std::string, Variable> InterfaceReader::user_variables(spv::ExecutionModel model,
                                                                spv::StorageClass storage) const {
    const auto entry = std::find_if(entries_.begin(), entries_.end(),
                                    [&](const Entry& e) { return e.model == uint32_t(model); });
    std::map<std::string, Variable> out;
    if (entry == entries_.end()) return out;
    for (uint32_t id : entry->interface) {
        const Def& v = def(id);
        if (v.op != spv::OpVariable || v.operands[1] != uint32_t(storage)) continue;
        const uint32_t pointee = def(v.operands[0]).operands[1];
        const Def& e = def(element(pointee));
        bool builtin_members = false;
        for (uint32_t i = 0; e.op == spv::OpTypeStruct && i < e.operands.size(); ++i)
            builtin_members |= has(element(pointee), i, spv::DecorationBuiltIn);
        if (has(id, UINT32_MAX, spv::DecorationBuiltIn) || builtin_members) continue;
        uint32_t location = 0, component = 0;
        has(id, UINT32_MAX, spv::DecorationLocation, &location);
        has(id, UINT32_MAX, spv::DecorationComponent, &component);
        const bool flat = has(id, UINT32_MAX, spv::DecorationFlat);
        const std::string key = std::to_string(location) + "." + std::to_string(component);
        EXPECT_FALSE(out.contains(key)) << "two variables at " << key;
        out[key] = {id, describe(pointee), flat, flat_ok(pointee, flat)};
    }
    return out;
}

size_t InterfaceReader::variables(spv::StorageClass storage) const {
    return size_t(std::count_if(defs_.begin(), defs_.end(), [&](const auto& d) {
        return d.second.op == spv::OpVariable && d.second.operands[1] == uint32_t(storage);
    }));
}

}  // namespace ds::layer::testing
