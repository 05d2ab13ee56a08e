#pragma once
// Fragment shaders compiled here (the project's compiler for SPIR-V 1.5, glslangValidator for
// the other versions, SPIRV-Tools' assembler for hand-written modules), rewritten by
// ds::layer::instrument_fragment (or made by ds::layer::measurement_fragment) and checked with
// SPIRV-Tools' validator in the Vulkan environment of each module's version.
// DS_INSTRUMENT_DUMP=DIR writes every module made to DIR (for spirv-val / spirv-dis by hand).
#include <gtest/gtest.h>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glslang/SPIRV/spirv.hpp>

#include "layer/spirv/instrument.h"
#include "tests/unit/shader/shader_test_fixture.h"

namespace ds::layer::testing {

// One instruction of a word stream: its opcode and operand words.
struct Op {
    spv::Op op;
    std::span<const uint32_t> operands;
};
std::vector<Op> split(std::span<const uint32_t> spirv);
size_t count(std::span<const uint32_t> spirv, spv::Op op);
// Decorations `decoration` with first literal `value` (e.g. BuiltIn FragCoord).
size_t count_decorations(std::span<const uint32_t> spirv, spv::Decoration decoration,
                         uint32_t value);
// The interface ids of the (first) Fragment entry point named `entry`.
std::vector<uint32_t> interface_of(std::span<const uint32_t> spirv, const std::string& entry);
// The variables decorated DescriptorSet `set`, and their Binding each, sorted by binding.
std::vector<uint32_t> bindings_in_set(std::span<const uint32_t> spirv, uint32_t set);

// "" when SPIRV-Tools' validator accepts the module in the Vulkan environment of its version,
// else its messages and the disassembly.
std::string validation_errors(std::span<const uint32_t> spirv);
// SPIR-V assembly to words of SPIR-V `version` (0x00010500: 1.5), for modules glslang does not
// write.
std::vector<uint32_t> assemble(const std::string& text, uint32_t version);

class InstrumentTest : public ds::shader::testing::ShaderTest {
  protected:
    // The project's compiler: SPIR-V 1.5.
    std::vector<uint32_t> compile(const std::string& source,
                                  ds::shader::Stage stage = ds::shader::Stage::Fragment);
    // glslangValidator --target-env `env` (vulkan1.0 .. vulkan1.3; extra arguments in `args`);
    // the stage is `file`'s extension (t.vert, t.tese, t.geom...).
    std::vector<uint32_t> compile_for(const std::string& source, const std::string& env,
                                      const std::string& args = "",
                                      const std::string& file = "t.frag");
    // instrument_fragment, with the output validated (a failure is reported, not thrown).
    InstrumentResult instrument(std::span<const uint32_t> spirv, const CounterBindings& b = {},
                                const std::string& entry = "main");
    // `body` inside main(), `decl` before it; one colour output.
    static std::string fragment(const std::string& decl, const std::string& body);
    // With DS_INSTRUMENT_DUMP=DIR: writes `spirv` to DIR/<suite>.<test>.<n>.spv.
    void dump(std::span<const uint32_t> spirv);

  private:
    int dumped_ = 0;  // DS_INSTRUMENT_DUMP files: <suite>.<test>.<n>.spv
};

// Runs `fn`, expects a ds::Error and returns its message.
template <typename Fn>
std::string thrown_message(Fn&& fn) {
    try {
        fn();
    } catch (const ds::Error& e) {
        return e.what();
    }
    ADD_FAILURE() << "no ds::Error thrown";
    return {};
}

}  // namespace ds::layer::testing
