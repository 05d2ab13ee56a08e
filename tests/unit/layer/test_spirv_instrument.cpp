// The layer's fragment shader rewrite (layer/spirv/instrument.h) on shaders compiled with the
// project's compiler (SPIR-V 1.5): where the counts go, which discards are counted, when early
// fragment tests are added, and the errors. Every rewritten module passes SPIRV-Tools' validator
// (InstrumentTest::instrument). Other SPIR-V versions and real shaders:
// test_spirv_instrument_modules.cpp.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "instrument_test_fixture.h"
#include "renderer/spirv/spirv_facts.h"

namespace ds::layer {
namespace {

using testing::count;
using testing::count_decorations;
using testing::interface_of;
using testing::split;
using testing::thrown_message;

class InstrumentFragmentTest : public testing::InstrumentTest {
  protected:
    // Rewrites `source` (compiled here) and checks the counts: two atomics more at the start, two
    // before each discard; early tests in the output exactly when `early_out`.
    InstrumentResult check(const std::string& source, uint32_t sites, bool added, bool early_out) {
        const std::vector<uint32_t> in = compile(source);
        const InstrumentResult r = instrument(in);
        EXPECT_EQ(r.discard_sites, sites);
        EXPECT_EQ(count(r.spirv, spv::OpAtomicIAdd), count(in, spv::OpAtomicIAdd) + 2 + 2 * sites);
        EXPECT_EQ(r.early_fragment_tests_added, added);
        EXPECT_EQ(spirv::read_fragment_facts(r.spirv).early_fragment_tests, early_out);
        return r;
    }
};

// The opcode just before each discard, demote and terminate.
std::vector<spv::Op> before_discards(const std::vector<uint32_t>& spirv) {
    const std::vector<testing::Op> ops = split(spirv);
    std::vector<spv::Op> out;
    for (size_t i = 1; i < ops.size(); ++i)
        if (ops[i].op == spv::OpKill || ops[i].op == spv::OpTerminateInvocation ||
            ops[i].op == spv::OpDemoteToHelperInvocation)
            out.push_back(ops[i - 1].op);
    return out;
}

constexpr const char* kEarly = "layout(early_fragment_tests) in;";

TEST_F(InstrumentFragmentTest, PlainShaderGetsEarlyTestsAndTwoCounts) {
    const InstrumentResult r = check(fragment("", ""), 0, true, true);
    // Two buffers at set 7, bindings 0 and 1; one relaxed atomic on each.
    EXPECT_EQ(testing::bindings_in_set(r.spirv, 7), (std::vector<uint32_t>{0, 1}));
    EXPECT_EQ(count_decorations(r.spirv, spv::DecorationBuiltIn, spv::BuiltInFragCoord), 1u);
    EXPECT_EQ(count(r.spirv, spv::OpExecutionMode), 2u);  // OriginUpperLeft, EarlyFragmentTests
    // No new capability; SPIR-V 1.5 needs no extension for the StorageBuffer class.
    EXPECT_EQ(count(r.spirv, spv::OpCapability), 1u);
    EXPECT_EQ(count(r.spirv, spv::OpExtension), 0u);
}

TEST_F(InstrumentFragmentTest, AlphaToCoverageKeepsLateTests) {
    // The pipeline turns the shader's alpha into coverage: early tests would write depth for
    // samples the coverage then drops, so none are added even to a plain shader.
    const std::vector<uint32_t> plain = compile(fragment("", ""));
    const InstrumentResult r = instrument_fragment(plain, "main", CounterBindings{}, true);
    EXPECT_FALSE(r.early_fragment_tests_added);
    EXPECT_EQ(count(r.spirv, spv::OpExecutionMode), 1u);  // OriginUpperLeft only
    EXPECT_TRUE(instrument_fragment(plain, "main", CounterBindings{}).early_fragment_tests_added);
}

TEST_F(InstrumentFragmentTest, CountsStartAfterTheEntryBlocksVariables) {
    // Locals (OpVariable Function) lead main's first block; the counts follow them, still in
    // that block, before main's own first instruction.
    const InstrumentResult r = check(fragment("",
                                              "float a[2] = float[2](0.0, 1.0); vec2 b = uv;\n"
                                              "a[int(uv.x)] = 2.0; color.x *= a[1] + b.y;"),
                                     0, true, true);
    const std::vector<testing::Op> ops = split(r.spirv);
    size_t label = 0, last_variable = 0, first_atomic = 0;
    for (size_t i = 0; i < ops.size(); ++i) {
        if (ops[i].op == spv::OpLabel && !label) label = i;
        if (ops[i].op == spv::OpVariable && label) last_variable = i;
        if (ops[i].op == spv::OpAtomicIAdd && !first_atomic) first_atomic = i;
    }
    ASSERT_GT(last_variable, label + 1);  // two locals
    EXPECT_GT(first_atomic, last_variable);
    for (size_t i = label + 1; i < first_atomic; ++i)
        EXPECT_TRUE(ops[i].op != spv::OpStore && ops[i].op != spv::OpLabel) << i;
}

TEST_F(InstrumentFragmentTest, AlphaTestDiscardIsOneSiteAndKeepsLateTests) {
    const InstrumentResult r = check(fragment("layout(set = 0, binding = 0) uniform sampler2D t;",
                                              "if (texture(t, uv).a < 0.5) discard;"),
                                     1, false, false);
    EXPECT_EQ(before_discards(r.spirv), std::vector<spv::Op>{spv::OpAtomicIAdd});
    EXPECT_EQ(count(r.spirv, spv::OpKill), 1u);
}

TEST_F(InstrumentFragmentTest, DiscardInACalledFunctionIsCounted) {
    const std::string source = R"(#version 460
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
void clip_below(float a, float b) { if (a < b) discard; }
void main() {
    color = vec4(uv, 0.0, 1.0);
    clip_below(uv.x, 0.25);
    clip_below(uv.y, 0.5);
}
)";
    const InstrumentResult r = check(source, 1, false, false);
    EXPECT_EQ(before_discards(r.spirv), std::vector<spv::Op>{spv::OpAtomicIAdd});
    // The discard's counts sit in clip_below, not in main.
    const std::vector<testing::Op> ops = split(r.spirv);
    size_t functions = 0, atomics_in_second = 0;
    for (const testing::Op& o : ops) {
        functions += o.op == spv::OpFunction;
        atomics_in_second += functions == 2 && o.op == spv::OpAtomicIAdd;
    }
    EXPECT_EQ(atomics_in_second, 2u);
}

TEST_F(InstrumentFragmentTest, EveryDiscardIsASite) {
    const InstrumentResult r = check(fragment("",
                                              "if (uv.x < 0.1) discard;\nif (uv.y < 0.1) discard;\n"
                                              "if (uv.x > 0.9) { color.r = 1.0; discard; }"),
                                     3, false, false);
    EXPECT_EQ(before_discards(r.spirv), std::vector<spv::Op>(3, spv::OpAtomicIAdd));
}

TEST_F(InstrumentFragmentTest, TerminateInvocationIsCounted) {
    const InstrumentResult r = check(fragment("#extension GL_EXT_terminate_invocation : require",
                                              "if (uv.x < 0.5) terminateInvocation;"),
                                     1, false, false);
    EXPECT_EQ(count(r.spirv, spv::OpTerminateInvocation), 1u);
    EXPECT_EQ(before_discards(r.spirv), std::vector<spv::Op>{spv::OpAtomicIAdd});
}

TEST_F(InstrumentFragmentTest, DemoteIsCounted) {
    // SPIR-V 1.5 with SPV_EXT_demote_to_helper_invocation (the EXT opcode: same value).
    const InstrumentResult r =
        check(fragment("#extension GL_EXT_demote_to_helper_invocation : require",
                       "if (uv.x < 0.5) demote;\ncolor.g = helperInvocationEXT() ? 1.0 : 0.0;"),
              1, false, false);
    EXPECT_EQ(count(r.spirv, spv::OpDemoteToHelperInvocation), 1u);
    EXPECT_EQ(before_discards(r.spirv), std::vector<spv::Op>{spv::OpAtomicIAdd});
}

TEST_F(InstrumentFragmentTest, WritesEarlyTestsWouldChangeKeepThemLate) {
    const std::pair<const char*, const char*> cases[] = {
        {"", "gl_FragDepth = uv.x;"},
        {"", "gl_SampleMask[0] = 1;"},
        {"layout(set = 0, binding = 0, std430) buffer B { uint n[]; } b;", "b.n[0] = 1u;"},
        {"layout(set = 0, binding = 0, r32ui) uniform uimage2D img;",
         "imageStore(img, ivec2(0), uvec4(1u));"},
        {"layout(set = 0, binding = 0, std430) buffer B { uint n; } b;", "atomicAdd(b.n, 1u);"},
        {"#extension GL_ARB_shader_stencil_export : require", "gl_FragStencilRefARB = 3;"},
    };
    for (const auto& [decl, body] : cases) {
        SCOPED_TRACE(body);
        check(fragment(decl, body), 0, false, false);
    }
}

TEST_F(InstrumentFragmentTest, ExistingEarlyTestsAreNotAddedTwice) {
    for (const char* body : {"", "if (uv.x < 0.5) discard;"}) {
        SCOPED_TRACE(body);
        const bool discards = body[0] != '\0';
        const InstrumentResult r = check(fragment(kEarly, body), discards, false, true);
        EXPECT_EQ(count(r.spirv, spv::OpExecutionMode), 2u);
    }
}

TEST_F(InstrumentFragmentTest, ExistingFragCoordIsReused) {
    const std::vector<uint32_t> in =
        compile(fragment("", "color.b = fract(gl_FragCoord.x * 0.5);"));
    const std::vector<uint32_t> before = interface_of(in, "main");
    const InstrumentResult r = instrument(in);
    EXPECT_EQ(count_decorations(r.spirv, spv::DecorationBuiltIn, spv::BuiltInFragCoord), 1u);
    // SPIR-V 1.5: the interface gains the two buffers only.
    EXPECT_EQ(interface_of(r.spirv, "main").size(), before.size() + 2);
}

TEST_F(InstrumentFragmentTest, MissingFragCoordJoinsTheInterface) {
    const std::vector<uint32_t> in = compile(fragment("", ""));
    ASSERT_EQ(count_decorations(in, spv::DecorationBuiltIn, spv::BuiltInFragCoord), 0u);
    const InstrumentResult r = instrument(in);
    EXPECT_EQ(count_decorations(r.spirv, spv::DecorationBuiltIn, spv::BuiltInFragCoord), 1u);
    EXPECT_EQ(interface_of(r.spirv, "main").size(), interface_of(in, "main").size() + 3);
}

TEST_F(InstrumentFragmentTest, BindingsAreTheCallers) {
    const InstrumentResult r =
        instrument(compile(fragment("", "")), {.set = 3, .draw_binding = 5, .pixel_binding = 2});
    EXPECT_EQ(testing::bindings_in_set(r.spirv, 3), (std::vector<uint32_t>{2, 5}));
    EXPECT_TRUE(testing::bindings_in_set(r.spirv, 7).empty());
}

TEST_F(InstrumentFragmentTest, ModuleUsingTheCounterSetThrows) {
    const std::vector<uint32_t> in = compile(
        fragment("layout(set = 7, binding = 3) uniform U { vec4 tint; };", "color *= tint;"));
    EXPECT_EQ(thrown_message([&] { instrument_fragment(in, "main", {}); }),
              "SPIR-V: the module already uses descriptor set 7, the set the counters need");
    EXPECT_NO_THROW(instrument_fragment(in, "main", {.set = 6}));
}

TEST_F(InstrumentFragmentTest, GarbageThrows) {
    const std::vector<uint32_t> garbage{1, 2, 3, 4, 5, 6, 7};
    EXPECT_EQ(thrown_message([&] { instrument_fragment(garbage, "main", {}); }),
              "SPIR-V: not a module (bad magic number or header)");
    EXPECT_NE(thrown_message([&] { instrument_fragment({}, "main", {}); }), "");
    const std::vector<uint32_t> good = compile(fragment("", ""));
    std::vector<uint32_t> unended = good;
    unended.pop_back();  // OpFunctionEnd
    EXPECT_EQ(thrown_message([&] { instrument_fragment(unended, "main", {}); }),
              "SPIR-V: the last function has no OpFunctionEnd");
    std::vector<uint32_t> truncated = good;
    truncated.back() = 2u << spv::WordCountShift | spv::OpFunctionEnd;  // one word past the end
    EXPECT_NE(thrown_message([&] { instrument_fragment(truncated, "main", {}); }).find("truncated"),
              std::string::npos);
}

TEST_F(InstrumentFragmentTest, NoFragmentEntryPointThrows) {
    const std::vector<uint32_t> vertex =
        compile(ds::shader::testing::kVertex, ds::shader::Stage::Vertex);
    EXPECT_EQ(thrown_message([&] { instrument_fragment(vertex, "main", {}); }),
              "SPIR-V: the module has no Fragment entry point named \"main\"");
    const std::vector<uint32_t> frag = compile(fragment("", ""));
    EXPECT_EQ(thrown_message([&] { instrument_fragment(frag, "mai", {}); }),
              "SPIR-V: the module has no Fragment entry point named \"mai\"");
}

TEST_F(InstrumentFragmentTest, EqualBindingsThrow) {
    const std::vector<uint32_t> in = compile(fragment("", ""));
    EXPECT_EQ(thrown_message([&] { instrument_fragment(in, "main", {.draw_binding = 1}); }),
              "SPIR-V instrument: the draw and pixel counters need different bindings");
}

}  // namespace
}  // namespace ds::layer
