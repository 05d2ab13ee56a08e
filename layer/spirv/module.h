#pragma once
// A SPIR-V module as the instrumenting rewrite edits it: the 5-word header and its instructions
// sorted into the sections of the logical layout (SPIR-V spec 2.4), so an addition goes to the
// end of its section and the output keeps the order. No SPIRV-Tools: spv:: enums only.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

// spv::HasResultAndType (module.cpp); defined here since any includer may come first in a batch.
#ifndef SPV_ENABLE_UTILITY_CODE
#define SPV_ENABLE_UTILITY_CODE
#endif
#include <glslang/SPIRV/spirv.hpp>

namespace ds::layer {

// One instruction: its opcode and operand words (the word count is recomputed on output).
struct Instruction {
    spv::Op op = spv::OpNop;
    std::vector<uint32_t> operands;

    uint32_t operand(size_t i) const { return i < operands.size() ? operands[i] : 0; }
};

// The logical layout's sections, in order. Global holds types, constants, global variables (and
// the OpLine / OpUndef / non-semantic OpExtInst among them); Function everything from the first
// OpFunction on.
enum class Section {
    Capability,
    Extension,
    ExtInstImport,
    MemoryModel,
    EntryPoint,
    ExecutionMode,
    DebugSource,  // OpString, OpSource, OpSourceContinued, OpSourceExtension
    DebugName,    // OpName, OpMemberName
    DebugModuleProcessed,
    Annotation,
    Global,
    Function,
    Count
};

// A literal string's words (UTF-8, NUL-terminated, padded with zeros to a whole word).
std::vector<uint32_t> string_words(std::string_view s);
// The literal string starting at words[0]; `words_used` gets how many words it takes. Throws
// ds::Error when it is not NUL-terminated within `words`.
std::string read_string(std::span<const uint32_t> words, size_t* words_used = nullptr);

class Module {
  public:
    // Throws ds::Error for anything that is not a whole SPIR-V module in layout order.
    explicit Module(std::span<const uint32_t> spirv);

    std::vector<uint32_t> words() const;

    uint32_t version() const { return header_[1]; }  // 0x00MMmm00: 0x00010300 is SPIR-V 1.3
    uint32_t new_id() { return header_[3]++; }       // the bound grows by one

    std::vector<Instruction>& section(Section s) { return sections_[size_t(s)]; }
    const std::vector<Instruction>& section(Section s) const { return sections_[size_t(s)]; }

    // Appends an instruction to the end of its section.
    void add(Section s, spv::Op op, std::vector<uint32_t> operands) {
        section(s).push_back({op, std::move(operands)});
    }
    // The id of the type `op` with these operands (after the result id) in Global, created at the
    // end of Global when absent: for the types SPIR-V requires unique (int, float, vector, bool).
    uint32_t type(spv::Op op, std::vector<uint32_t> operands);
    // A new OpConstant of `type`.
    uint32_t constant(uint32_t type, uint32_t value);

    // The instruction in Global whose result id is `id` (types, constants, variables), or null.
    const Instruction* global(uint32_t id) const;

  private:
    std::array<uint32_t, 5> header_{};
    std::array<std::vector<Instruction>, size_t(Section::Count)> sections_;
};

}  // namespace ds::layer
