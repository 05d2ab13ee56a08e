// The survival fragment shader (layer/spirv/survival.h) on a spread of fragment shaders and
// SPIR-V versions: every output passes SPIRV-Tools' validator, has no Output variable, writes
// memory only in the layer's buffers (or Function / Private / Workgroup), has one survival
// sequence before each return of its entry function, keeps its discards, and has early
// fragment tests exactly when asked (or there before). Errors and other checks:
// test_survival_modules.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "instrument_test_fixture.h"
#include "layer/spirv/survival.h"
#include "measure_test_reader.h"
#include "survival_test_reader.h"

namespace ds::layer {
namespace {

using testing::count;
using testing::count_decorations;
using testing::interface_of;
using testing::SurvivalFacts;

class SurvivalFragmentTest : public testing::InstrumentTest {
  protected:
    // survival_fragment on `in` with the checks every output passes; its facts.
    SurvivalFacts survive(std::span<const uint32_t> in, const SurvivalOptions& o = {},
                          const SurvivalBindings& b = {}) {
        EXPECT_EQ(testing::validation_errors(in), "") << "the input is not valid";
        out_ = survival_fragment(in, "main", b, o);
        dump(out_);
        EXPECT_EQ(testing::validation_errors(out_), "");
        EXPECT_EQ(out_.at(1), in[1]);  // SPIR-V version
        const SurvivalFacts before = testing::read_survival(in, b.set);
        const SurvivalFacts f =
            testing::read_survival(out_, b.set, b.zpixel_binding, b.record_binding);
        const size_t returns = testing::entry_returns(in);
        EXPECT_EQ(f.output_variables, 0u);
        EXPECT_EQ(f.output_pointer_types, 0u);
        EXPECT_EQ(f.foreign_writes, 0u);
        EXPECT_EQ(f.umin_per_return, std::vector<size_t>(returns, 1));
        EXPECT_EQ(f.returns_after_record, returns);
        EXPECT_EQ(f.umin_elsewhere, 0u);
        EXPECT_EQ(count(out_, spv::OpAtomicUMax), returns);
        EXPECT_EQ(f.discards, before.discards);
        EXPECT_EQ(f.early_fragment_tests, o.early_fragment_tests || before.early_fragment_tests);
        EXPECT_EQ(f.depth_modes, 0u);
        std::vector<uint32_t> bindings{b.draw_binding, b.zpixel_binding, b.record_binding};
        std::sort(bindings.begin(), bindings.end());
        EXPECT_EQ(testing::bindings_in_set(out_, b.set), bindings);
        return f;
    }

    std::vector<uint32_t> out_;  // the last survival shader
};

struct Case {
    const char* name;
    const char* decl;
    const char* body;
};

// One colour output at location 0, uv input at location 0 (InstrumentTest::fragment).
const Case kCases[] = {
    {"plain", "", ""},
    {"alpha test", "layout(set = 0, binding = 0) uniform sampler2D t;",
     "if (texture(t, uv).a < 0.5) discard;"},
    {"demote", "#extension GL_EXT_demote_to_helper_invocation : require",
     "if (uv.x < 0.5) demote;\ncolor.g = helperInvocationEXT() ? 1.0 : 0.0;"},
    {"terminate", "#extension GL_EXT_terminate_invocation : require",
     "if (uv.x < 0.5) terminateInvocation;"},
    {"frag depth", "layout(depth_greater) out float gl_FragDepth;", "gl_FragDepth = uv.x;"},
    {"sample mask", "", "gl_SampleMask[0] = int(uv.x * 4.0);"},
    {"stencil export", "#extension GL_ARB_shader_stencil_export : require",
     "gl_FragStencilRefARB = 3;"},
    {"ssbo", "layout(set = 0, binding = 0, std430) buffer B { uint n[8]; float f; } b;",
     "b.n[0] = 1u; uint old = atomicAdd(b.n[1], 2u);\n"
     "b.n[2] = atomicExchange(b.n[3], old); b.f = uv.y;\n"
     "color.r = float(atomicCompSwap(b.n[4], 1u, 2u) + atomicMin(b.n[5], 3u));"},
    {"image", "layout(set = 0, binding = 1, r32ui) uniform uimage2D img;",
     "imageStore(img, ivec2(0), uvec4(1u));\n"
     "color.g = float(imageAtomicAdd(img, ivec2(1), 1u) + imageAtomicCompSwap(img, ivec2(2), "
     "0u, 1u));"},
    {"early tests", "layout(early_fragment_tests) in;", "color.b = 0.5;"},
    {"frag coord", "", "color.b = fract(gl_FragCoord.x * 0.5);"},
};

// Returns: an early one in main, and returns of a called function (not instrumented).
constexpr const char* kReturns = R"(#version 460
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
float step_at(float a, float b) { if (a < b) return 0.0; return 1.0; }
void main() {
    color = vec4(step_at(uv.x, 0.5));
    if (uv.y < 0.25) return;
    color.g = step_at(uv.y, 0.75);
    if (color.g > 0.5) discard;
}
)";

TEST_F(SurvivalFragmentTest, EveryCaseAtSpirv15) {
    for (const Case& c : kCases) {
        SCOPED_TRACE(c.name);
        const std::vector<uint32_t> in = compile(fragment(c.decl, c.body));
        survive(in);
        survive(in, {.instance_location = 1, .early_fragment_tests = true});
    }
}

TEST_F(SurvivalFragmentTest, EveryCaseAtEverySpirvVersion) {
    for (const char* env :
         {"vulkan1.0", "vulkan1.1", "vulkan1.1 --target-env spirv1.4", "vulkan1.2", "vulkan1.3"}) {
        for (const Case& c : kCases) {
            SCOPED_TRACE(std::string(env) + ": " + c.name);
            const std::vector<uint32_t> in = compile_for(fragment(c.decl, c.body), env);
            ASSERT_GT(in.size(), 5u);
            survive(in);
            survive(in, {.instance_location = 2, .early_fragment_tests = true});
        }
    }
}

TEST_F(SurvivalFragmentTest, EarlyReturnsOfMainOnly) {
    const std::vector<uint32_t> in = compile(kReturns);
    ASSERT_EQ(testing::entry_returns(in), 2u);
    ASSERT_GT(count(in, spv::OpReturnValue), 1u);  // step_at's
    const SurvivalFacts f = survive(in);
    EXPECT_EQ(f.umin_per_return.size(), 2u);
    EXPECT_EQ(count(out_, spv::OpAtomicUMin), 2u);
    survive(compile_for(kReturns, "vulkan1.0"), {.instance_location = 1});
}

TEST_F(SurvivalFragmentTest, MemoryReadModifyWritesBecomeLoads) {
    // ssbo: atomicAdd, atomicExchange, atomicCompSwap, atomicMin; image: two atomics.
    for (const Case& c : {kCases[7], kCases[8]}) {
        SCOPED_TRACE(c.name);
        const std::vector<uint32_t> in = compile(fragment(c.decl, c.body));
        const size_t atomics = c.name == std::string("ssbo") ? 4 : 2;
        ASSERT_EQ(count(in, spv::OpAtomicIAdd) + count(in, spv::OpAtomicExchange) +
                      count(in, spv::OpAtomicCompareExchange) + count(in, spv::OpAtomicUMin),
                  atomics);
        const SurvivalFacts f = survive(in);
        EXPECT_EQ(f.atomic_loads, atomics + 1);  // and the nearest depth's
        EXPECT_EQ(count(out_, spv::OpImageWrite), 0u);
        // The layer's own: min, max, the EQUAL count and the record count.
        EXPECT_EQ(count(out_, spv::OpAtomicIAdd), 2u);
        EXPECT_EQ(count(out_, spv::OpAtomicUMin), 1u);
        EXPECT_EQ(count(out_, spv::OpAtomicExchange) + count(out_, spv::OpAtomicCompareExchange),
                  0u);
    }
}

TEST_F(SurvivalFragmentTest, OutputsBecomePrivate) {
    const std::vector<uint32_t> in = compile_for(fragment("", "gl_FragDepth = uv.x;"), "vulkan1.0");
    const std::vector<uint32_t> in_interface = interface_of(in, "main");
    ASSERT_EQ(in_interface.size(), 3u);  // uv, color, gl_FragDepth
    survive(in);
    EXPECT_EQ(count_decorations(out_, spv::DecorationBuiltIn, spv::BuiltInFragDepth), 0u);
    EXPECT_EQ(count(out_, spv::OpExecutionMode), 1u);  // OriginUpperLeft; DepthReplacing went
    // Below SPIR-V 1.4 the interface holds uv and the new FragCoord; from 1.4 on also the two
    // former outputs and the three buffers.
    EXPECT_EQ(interface_of(out_, "main").size(), 2u);
    survive(compile_for(fragment("", "gl_FragDepth = uv.x;"), "vulkan1.3"));
    EXPECT_EQ(interface_of(out_, "main").size(), 7u);
}

TEST_F(SurvivalFragmentTest, InstanceInputIsFlatUintAtItsLocation) {
    const std::vector<uint32_t> in = compile(fragment("", ""));
    survive(in, {.instance_location = 5});
    const auto inputs = testing::InterfaceReader(out_).user_variables(spv::ExecutionModelFragment,
                                                                      spv::StorageClassInput);
    ASSERT_EQ(inputs.size(), 2u);  // uv and the instance
    EXPECT_EQ(inputs.at("5.0").type, "u32");
    EXPECT_TRUE(inputs.at("5.0").flat);
    survive(in);
    EXPECT_EQ(testing::InterfaceReader(out_)
                  .user_variables(spv::ExecutionModelFragment, spv::StorageClassInput)
                  .size(),
              1u);
}

}  // namespace
}  // namespace ds::layer
