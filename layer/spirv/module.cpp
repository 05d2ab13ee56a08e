#include "layer/spirv/module.h"

#include <algorithm>

#include "renderer/common/error.h"

namespace ds::layer {

namespace {

constexpr size_t kHeaderWords = 5;

// The section an instruction before the first OpFunction belongs to.
Section section_of(spv::Op op) {
    switch (op) {
        case spv::OpCapability:
            return Section::Capability;
        case spv::OpExtension:
            return Section::Extension;
        case spv::OpExtInstImport:
            return Section::ExtInstImport;
        case spv::OpMemoryModel:
            return Section::MemoryModel;
        case spv::OpEntryPoint:
            return Section::EntryPoint;
        case spv::OpExecutionMode:
        case spv::OpExecutionModeId:
            return Section::ExecutionMode;
        case spv::OpString:
        case spv::OpSource:
        case spv::OpSourceContinued:
        case spv::OpSourceExtension:
            return Section::DebugSource;
        case spv::OpName:
        case spv::OpMemberName:
            return Section::DebugName;
        case spv::OpModuleProcessed:
            return Section::DebugModuleProcessed;
        case spv::OpDecorate:
        case spv::OpMemberDecorate:
        case spv::OpDecorationGroup:
        case spv::OpGroupDecorate:
        case spv::OpGroupMemberDecorate:
        case spv::OpDecorateId:
        case spv::OpDecorateString:
        case spv::OpMemberDecorateString:
            return Section::Annotation;
        case spv::OpFunction:
            return Section::Function;
        default:
            return Section::Global;
    }
}

// Every OpFunction closed by an OpFunctionEnd before the next one, the last one too.
void check_functions(const std::vector<Instruction>& functions) {
    bool open = false;
    for (const Instruction& in : functions) {
        if (in.op == spv::OpFunction && open)
            throw Error("SPIR-V: an OpFunction starts inside another function");
        if (in.op == spv::OpFunctionEnd && !open)
            throw Error("SPIR-V: an OpFunctionEnd is outside any function");
        if (in.op == spv::OpFunction || in.op == spv::OpFunctionEnd)
            open = in.op == spv::OpFunction;
    }
    if (open) throw Error("SPIR-V: the last function has no OpFunctionEnd");
}

}  // namespace

std::vector<uint32_t> string_words(std::string_view s) {
    std::vector<uint32_t> out(s.size() / 4 + 1, 0u);  // room for the NUL
    for (size_t i = 0; i < s.size(); ++i)
        out[i / 4] |= uint32_t(static_cast<unsigned char>(s[i])) << (8 * (i % 4));
    return out;
}

std::string read_string(std::span<const uint32_t> words, size_t* words_used) {
    std::string out;
    for (size_t w = 0; w < words.size(); ++w) {
        for (size_t b = 0; b < 4; ++b) {
            const char c = char((words[w] >> (8 * b)) & 0xffu);
            if (c == '\0') {
                if (words_used) *words_used = w + 1;
                return out;
            }
            out += c;
        }
    }
    throw Error("SPIR-V: a literal string is not NUL-terminated within its instruction");
}

Module::Module(std::span<const uint32_t> spirv) {
    if (spirv.size() < kHeaderWords || spirv[0] != spv::MagicNumber)
        throw Error("SPIR-V: not a module (bad magic number or header)");
    std::copy_n(spirv.begin(), kHeaderWords, header_.begin());
    if (header_[3] == 0) throw Error("SPIR-V: the header's id bound is 0");
    Section current = Section::Capability;
    for (size_t at = kHeaderWords; at < spirv.size();) {
        const uint32_t count = spirv[at] >> spv::WordCountShift;
        if (count == 0 || at + count > spirv.size())
            throw Error("SPIR-V: truncated instruction at word " + std::to_string(at));
        const auto op = spv::Op(spirv[at] & spv::OpCodeMask);
        if (current != Section::Function) {
            const Section s = section_of(op);
            if (s < current)
                throw Error("SPIR-V: instruction at word " + std::to_string(at) +
                            " is out of the logical layout order");
            current = s;
        }
        const auto operands = spirv.subspan(at + 1, count - 1);
        section(current).push_back({op, {operands.begin(), operands.end()}});
        at += count;
    }
    check_functions(section(Section::Function));
}

std::vector<uint32_t> Module::words() const {
    std::vector<uint32_t> out(header_.begin(), header_.end());
    for (const auto& s : sections_) {
        for (const Instruction& in : s) {
            out.push_back(uint32_t(in.operands.size() + 1) << spv::WordCountShift | in.op);
            out.insert(out.end(), in.operands.begin(), in.operands.end());
        }
    }
    return out;
}

uint32_t Module::type(spv::Op op, std::vector<uint32_t> operands) {
    for (const Instruction& in : section(Section::Global)) {
        if (in.op == op && in.operands.size() == operands.size() + 1 &&
            std::equal(operands.begin(), operands.end(), in.operands.begin() + 1))
            return in.operand(0);
    }
    const uint32_t id = new_id();
    operands.insert(operands.begin(), id);
    add(Section::Global, op, std::move(operands));
    return id;
}

uint32_t Module::constant(uint32_t type, uint32_t value) {
    const uint32_t id = new_id();
    add(Section::Global, spv::OpConstant, {type, id, value});
    return id;
}

const Instruction* Module::global(uint32_t id) const {
    for (const Instruction& in : section(Section::Global)) {
        bool has_result = false, has_type = false;
        spv::HasResultAndType(in.op, &has_result, &has_type);
        if (has_result && in.operand(has_type ? 1 : 0) == id) return &in;
    }
    return nullptr;
}

}  // namespace ds::layer
