// The fragment shader rewrite across modules: SPIR-V 1.0 to 1.6 (glslangValidator), the Vulkan
// memory model, debug information, depthscope's own shaders, and hand-written modules with two
// Fragment entry points. Every rewritten module passes SPIRV-Tools' validator.
#include <gtest/gtest.h>

#include <set>
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

class InstrumentModuleTest : public testing::InstrumentTest {};

// The values of the scope operands of every OpAtomicIAdd.
std::set<uint32_t> atomic_scopes(const std::vector<uint32_t>& spirv) {
    std::map<uint32_t, uint32_t> constants;
    std::set<uint32_t> out;
    for (const testing::Op& o : split(spirv)) {
        if (o.op == spv::OpConstant) constants[o.operands[1]] = o.operands[2];
        if (o.op == spv::OpAtomicIAdd) out.insert(constants.at(o.operands[3]));
    }
    return out;
}

constexpr const char* kDiscard = "if (uv.x < 0.5) discard;";

TEST_F(InstrumentModuleTest, EverySpirvVersion) {
    struct Case {
        const char* env;
        uint32_t version;
    };
    for (const Case& c : {Case{"vulkan1.0", 0x10000}, Case{"vulkan1.1", 0x10300},
                          Case{"vulkan1.1 --target-env spirv1.4", 0x10400},
                          Case{"vulkan1.2", 0x10500}, Case{"vulkan1.3", 0x10600}}) {
        SCOPED_TRACE(c.env);
        for (const char* body : {"", kDiscard}) {
            const std::vector<uint32_t> in = compile_for(fragment("", body), c.env);
            ASSERT_GT(in.size(), 5u);
            ASSERT_EQ(in[1], c.version);
            const InstrumentResult r = instrument(in);
            EXPECT_EQ(r.spirv[1], c.version);
            EXPECT_EQ(r.discard_sites, body[0] ? 1u : 0u);
            EXPECT_EQ(r.early_fragment_tests_added, !body[0]);
            EXPECT_EQ(count(r.spirv, spv::OpAtomicIAdd), 2 + 2 * r.discard_sites);
            // Before 1.3 the StorageBuffer class needs its extension; before 1.4 only Input
            // and Output variables are in the interface (here FragCoord).
            EXPECT_EQ(count(r.spirv, spv::OpExtension), c.version < 0x10300 ? 1u : 0u);
            EXPECT_EQ(interface_of(r.spirv, "main").size(),
                      interface_of(in, "main").size() + (c.version < 0x10400 ? 1 : 3));
            EXPECT_EQ(count(r.spirv, spv::OpCapability), count(in, spv::OpCapability));
        }
    }
}

TEST_F(InstrumentModuleTest, DemoteIsCoreInSpirv16) {
    const InstrumentResult r =
        instrument(compile_for(fragment("#extension GL_EXT_demote_to_helper_invocation : require",
                                        "if (uv.x < 0.5) demote;"),
                               "vulkan1.3"));
    EXPECT_EQ(r.discard_sites, 1u);
    EXPECT_FALSE(r.early_fragment_tests_added);
    EXPECT_EQ(count(r.spirv, spv::OpAtomicIAdd), 4u);
}

TEST_F(InstrumentModuleTest, ScopeIsDeviceUnderGlsl450) {
    const InstrumentResult r = instrument(compile(fragment("", kDiscard)));
    EXPECT_EQ(atomic_scopes(r.spirv), std::set<uint32_t>{spv::ScopeDevice});
}

TEST_F(InstrumentModuleTest, VulkanMemoryModelUsesQueueFamilyScope) {
    const std::string decl =
        "#pragma use_vulkan_memory_model\n#extension GL_KHR_memory_scope_semantics : require";
    for (const char* env : {"vulkan1.2", "vulkan1.3"}) {
        SCOPED_TRACE(env);
        const std::vector<uint32_t> in = compile_for(fragment(decl, kDiscard), env);
        const InstrumentResult r = instrument(in);
        EXPECT_EQ(r.discard_sites, 1u);
        EXPECT_EQ(atomic_scopes(r.spirv), std::set<uint32_t>{spv::ScopeQueueFamily});
        EXPECT_EQ(count(r.spirv, spv::OpCapability), count(in, spv::OpCapability));
    }
}

TEST_F(InstrumentModuleTest, DebugInformationStaysIntact) {
    const std::string source = fragment("", "float a = uv.x * 2.0;\nif (a < 0.5) discard;");
    for (const char* args : {"-g", "-gVS"}) {
        SCOPED_TRACE(args);
        const std::vector<uint32_t> in = compile_for(source, "vulkan1.3", args);
        const InstrumentResult r = instrument(in);
        EXPECT_EQ(r.discard_sites, 1u);
        for (spv::Op op : {spv::OpLine, spv::OpString, spv::OpSource, spv::OpExtInst})
            EXPECT_EQ(count(r.spirv, op), count(in, op)) << op;
    }
    // Line information and the source text in SPIR-V 1.0 too.
    const std::vector<uint32_t> old = compile_for(source, "vulkan1.0", "-g");
    ASSERT_GT(count(old, spv::OpLine), 0u);
    EXPECT_EQ(count(instrument(old).spirv, spv::OpLine), count(old, spv::OpLine));
}

// depthscope's own shaders, compiled as the renderer does.
struct RealShader {
    const char* file;
    const char* alpha_mask;
    uint32_t sites;
};

TEST_F(InstrumentModuleTest, DepthscopesOwnShaders) {
    ds::shader::Compiler compiler(ds::shader::Compiler::default_shader_root(), "");
    for (const RealShader& s :
         {RealShader{"forward.frag", nullptr, 0}, RealShader{"forward.frag", "1", 1},
          RealShader{"depth_prepass.frag", nullptr, 0}, RealShader{"depth_prepass.frag", "1", 1}}) {
        SCOPED_TRACE(std::string(s.file) + (s.alpha_mask ? " ALPHA_MASK=1" : ""));
        std::vector<ds::shader::Define> defines;
        if (s.alpha_mask) defines.push_back({"ALPHA_MASK", s.alpha_mask});
        const auto in = compiler.compile(s.file, ds::shader::Stage::Fragment, defines).spirv;
        const InstrumentResult r = instrument(in);
        EXPECT_EQ(r.discard_sites, s.sites);
        EXPECT_EQ(r.early_fragment_tests_added, s.sites == 0);
        EXPECT_EQ(spirv::read_fragment_facts(r.spirv).early_fragment_tests, s.sites == 0);
        EXPECT_EQ(count(r.spirv, spv::OpAtomicIAdd), 2 + 2 * s.sites);
    }
}

// Two Fragment entry points, "a" and "b", and a Vertex one also named "a". b reads FragCoord and
// calls a function that discards; a does neither.
constexpr const char* kTwoEntries = R"(
OpCapability Shader
OpMemoryModel Logical GLSL450
OpEntryPoint Vertex %v "a"
OpEntryPoint Fragment %a "a" %out
OpEntryPoint Fragment %b "b" %out %coord
OpExecutionMode %a OriginUpperLeft
OpExecutionMode %b OriginUpperLeft
OpDecorate %out Location 0
OpDecorate %coord BuiltIn FragCoord
%void = OpTypeVoid
%fn = OpTypeFunction %void
%float = OpTypeFloat 32
%v4 = OpTypeVector %float 4
%ptr_out = OpTypePointer Output %v4
%ptr_in = OpTypePointer Input %v4
%out = OpVariable %ptr_out Output
%coord = OpVariable %ptr_in Input
%one = OpConstant %float 1
%white = OpConstantComposite %v4 %one %one %one %one
%v = OpFunction %void None %fn
%v0 = OpLabel
OpReturn
OpFunctionEnd
%a = OpFunction %void None %fn
%a0 = OpLabel
OpStore %out %white
OpReturn
OpFunctionEnd
%b = OpFunction %void None %fn
%b0 = OpLabel
%c = OpLoad %v4 %coord
OpStore %out %c
%r = OpFunctionCall %void %kill
OpReturn
OpFunctionEnd
%kill = OpFunction %void None %fn
%k0 = OpLabel
OpKill
OpFunctionEnd
)";

TEST_F(InstrumentModuleTest, TwoFragmentEntryPointsShareTheCounters) {
    for (uint32_t version : {0x10300u, 0x10500u}) {
        SCOPED_TRACE(version);
        const std::vector<uint32_t> in = testing::assemble(kTwoEntries, version);
        // Entry a: counted at its start; b's discard (in a function only b calls) counts too,
        // so b's interface gains what it now uses. The module discards: no early tests.
        const InstrumentResult r = instrument(in, {}, "a");
        EXPECT_EQ(r.discard_sites, 1u);
        EXPECT_FALSE(r.early_fragment_tests_added);
        EXPECT_EQ(count(r.spirv, spv::OpAtomicIAdd), 4u);
        // b's FragCoord is reused, and joins a's interface.
        EXPECT_EQ(count_decorations(r.spirv, spv::DecorationBuiltIn, spv::BuiltInFragCoord), 1u);
        const size_t added = version < 0x10400 ? 1 : 3;
        EXPECT_EQ(interface_of(r.spirv, "a").size(), 1 + added);
        EXPECT_EQ(interface_of(r.spirv, "b").size(), 2 + added - 1);  // FragCoord was there
    }
}

TEST_F(InstrumentModuleTest, UncalledDiscardIsCountedAndOtherEntriesStayAsTheyWere) {
    // Without b's call, only a (the named entry) changes, and it gets early tests.
    std::string text = kTwoEntries;
    text.replace(text.find("%r = OpFunctionCall %void %kill\n"), 32, "");
    const std::vector<uint32_t> in = testing::assemble(text, 0x10500);
    const InstrumentResult r = instrument(in, {}, "a");
    EXPECT_EQ(r.discard_sites, 1u);              // still counted where it is
    EXPECT_FALSE(r.early_fragment_tests_added);  // the module's facts see the OpKill
    EXPECT_EQ(interface_of(r.spirv, "b"), interface_of(in, "b"));
    const InstrumentResult rb = instrument(in, {}, "b");
    EXPECT_EQ(interface_of(rb.spirv, "a"), interface_of(in, "a"));
}

}  // namespace
}  // namespace ds::layer
