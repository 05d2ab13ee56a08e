// The survival fragment shader (layer/spirv/survival.h) beyond the spread of shaders of
// test_survival_fragment.cpp: the Vulkan memory model, buffer references, depthscope's own
// shaders, the bindings, the errors, and reads_input_attachments. Every output passes
// SPIRV-Tools' validator.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>
#include <vector>

#include "instrument_test_fixture.h"
#include "layer/spirv/survival.h"
#include "survival_test_reader.h"

namespace ds::layer {
namespace {

using testing::count;
using testing::split;
using testing::thrown_message;

class SurvivalModuleTest : public testing::InstrumentTest {
  protected:
    std::vector<uint32_t> survive(std::span<const uint32_t> in, const SurvivalBindings& b = {},
                                  const SurvivalOptions& o = {}) {
        EXPECT_EQ(testing::validation_errors(in), "") << "the input is not valid";
        std::vector<uint32_t> out = survival_fragment(in, "main", b, o);
        dump(out);
        EXPECT_EQ(testing::validation_errors(out), "");
        const testing::SurvivalFacts f =
            testing::read_survival(out, b.set, b.zpixel_binding, b.record_binding);
        EXPECT_EQ(f.foreign_writes, 0u);
        EXPECT_EQ(f.output_variables, 0u);
        EXPECT_EQ(f.umin_per_return, std::vector<size_t>(testing::entry_returns(in), 1));
        return out;
    }
};

// The values of the constants each atomic's operand `operand` names, by opcode.
std::map<spv::Op, std::set<uint32_t>> atomic_operands(const std::vector<uint32_t>& spirv,
                                                      size_t operand) {
    std::map<uint32_t, uint32_t> constants;
    std::map<spv::Op, std::set<uint32_t>> out;
    for (const testing::Op& o : split(spirv)) {
        if (o.op == spv::OpConstant) constants[o.operands[1]] = o.operands[2];
        if (o.op == spv::OpAtomicIAdd || o.op == spv::OpAtomicLoad || o.op == spv::OpAtomicUMin)
            out[o.op].insert(constants.at(o.operands[operand]));
    }
    return out;
}

constexpr const char* kMemoryModel =
    "#pragma use_vulkan_memory_model\n#extension GL_KHR_memory_scope_semantics : require\n"
    "layout(set = 0, binding = 0, std430) buffer B { uint n; } b;";

TEST_F(SurvivalModuleTest, VulkanMemoryModel) {
    // An acquire-release atomic on the application's buffer becomes an acquire load; the
    // layer's atomics are relaxed, QueueFamily scope.
    const std::string body =
        "color.r = float(atomicAdd(b.n, 1u, gl_ScopeDevice, gl_StorageSemanticsBuffer, "
        "gl_SemanticsAcquireRelease));";
    for (const char* env : {"vulkan1.2", "vulkan1.3"}) {
        SCOPED_TRACE(env);
        const std::vector<uint32_t> out = survive(compile_for(fragment(kMemoryModel, body), env));
        EXPECT_EQ(atomic_operands(out, 3).at(spv::OpAtomicIAdd),
                  std::set<uint32_t>{spv::ScopeQueueFamily});
        EXPECT_EQ(atomic_operands(out, 4).at(spv::OpAtomicIAdd), std::set<uint32_t>{0});
        EXPECT_EQ(atomic_operands(out, 4).at(spv::OpAtomicLoad),
                  (std::set<uint32_t>{
                      0, spv::MemorySemanticsAcquireMask | spv::MemorySemanticsUniformMemoryMask}));
    }
}

TEST_F(SurvivalModuleTest, DeviceScopeUnderGlsl450) {
    const std::vector<uint32_t> out = survive(compile(fragment("", "")));
    EXPECT_EQ(atomic_operands(out, 3).at(spv::OpAtomicUMin), std::set<uint32_t>{spv::ScopeDevice});
}

TEST_F(SurvivalModuleTest, BufferReferenceWritesGo) {
    const std::string decl = R"(#extension GL_EXT_buffer_reference : require
layout(buffer_reference) buffer Node;
layout(buffer_reference, std430) buffer Node { uint value; Node next; };
layout(set = 0, binding = 0) uniform U { Node head; };)";
    const std::string body = "head.value = 3u; head.next.value = atomicAdd(head.value, 1u);";
    for (const char* env : {"vulkan1.2", "vulkan1.3"}) {
        SCOPED_TRACE(env);
        const std::vector<uint32_t> in = compile_for(fragment(decl, body), env);
        ASSERT_EQ(count(in, spv::OpStore), 3u);  // color, and two through references
        const std::vector<uint32_t> out = survive(in);
        EXPECT_EQ(count(out, spv::OpAtomicLoad), 2u);
    }
}

// Writes glslang does not write: OpAtomicStore (release), OpCopyMemory, the atomic flags (Kernel
// instructions: the input is not a valid Vulkan module, the output is), an increment with
// release semantics.
constexpr const char* kHandWrittenWrites = R"(
OpCapability Shader
OpMemoryModel Logical GLSL450
OpEntryPoint Fragment %main "main" %out %b
OpExecutionMode %main OriginUpperLeft
OpDecorate %out Location 0
OpDecorate %B Block
OpMemberDecorate %B 0 Offset 0
OpMemberDecorate %B 1 Offset 4
OpDecorate %b DescriptorSet 0
OpDecorate %b Binding 0
%void = OpTypeVoid
%fn = OpTypeFunction %void
%uint = OpTypeInt 32 0
%bool = OpTypeBool
%B = OpTypeStruct %uint %uint
%ptr_B = OpTypePointer StorageBuffer %B
%ptr_u = OpTypePointer StorageBuffer %uint
%ptr_out = OpTypePointer Output %uint
%b = OpVariable %ptr_B StorageBuffer
%out = OpVariable %ptr_out Output
%u0 = OpConstant %uint 0
%u1 = OpConstant %uint 1
%release = OpConstant %uint 68
%main = OpFunction %void None %fn
%label = OpLabel
%p0 = OpAccessChain %ptr_u %b %u0
%p1 = OpAccessChain %ptr_u %b %u1
OpAtomicStore %p0 %u1 %release %u1
OpCopyMemory %p1 %p0
%flag = OpAtomicFlagTestAndSet %bool %p0 %u1 %u0
OpAtomicFlagClear %p1 %u1 %u0
%x = OpAtomicIIncrement %uint %p1 %u1 %release
%y = OpSelect %uint %flag %x %u0
OpStore %out %y
OpReturn
OpFunctionEnd
)";

TEST_F(SurvivalModuleTest, HandWrittenWrites) {
    const std::vector<uint32_t> in = testing::assemble(kHandWrittenWrites, 0x10500);
    ASSERT_GT(in.size(), 5u);
    const std::vector<uint32_t> out = survival_fragment(in, "main", {});
    dump(out);
    EXPECT_EQ(testing::validation_errors(out), "");
    const testing::SurvivalFacts f = testing::read_survival(out);
    EXPECT_EQ(f.foreign_writes, 0u);
    EXPECT_EQ(f.umin_per_return, std::vector<size_t>{1});
    for (spv::Op op : {spv::OpAtomicStore, spv::OpCopyMemory, spv::OpAtomicFlagTestAndSet,
                       spv::OpAtomicFlagClear, spv::OpAtomicIIncrement})
        EXPECT_EQ(count(out, op), 0u) << op;
    // The flag's and the increment's loads (and the nearest depth's); the flag compared with 0.
    EXPECT_EQ(count(out, spv::OpAtomicLoad), 3u);
    EXPECT_EQ(count(out, spv::OpINotEqual), 1u);
    // Release dropped from the increment's semantics, UniformMemory kept.
    EXPECT_EQ(atomic_operands(out, 4).at(spv::OpAtomicLoad),
              (std::set<uint32_t>{0, spv::MemorySemanticsUniformMemoryMask}));
}

// depthscope's own shaders, compiled as the renderer does.
TEST_F(SurvivalModuleTest, DepthscopesOwnShaders) {
    ds::shader::Compiler compiler(ds::shader::Compiler::default_shader_root(), "");
    for (const char* file : {"forward.frag", "depth_prepass.frag"}) {
        for (const char* alpha : {"0", "1"}) {
            SCOPED_TRACE(std::string(file) + " ALPHA_MASK=" + alpha);
            std::vector<ds::shader::Define> defines;
            if (alpha[0] == '1') defines.push_back({"ALPHA_MASK", alpha});
            survive(compiler.compile(file, ds::shader::Stage::Fragment, defines).spirv);
        }
    }
}

TEST_F(SurvivalModuleTest, BindingsAreTheCallers) {
    const std::vector<uint32_t> out =
        survive(compile(fragment("", "")),
                {.set = 3, .draw_binding = 5, .zpixel_binding = 1, .record_binding = 0});
    EXPECT_EQ(testing::bindings_in_set(out, 3), (std::vector<uint32_t>{0, 1, 5}));
    EXPECT_TRUE(testing::bindings_in_set(out, 7).empty());
}

TEST_F(SurvivalModuleTest, Errors) {
    const std::vector<uint32_t> frag = compile(fragment("", ""));
    EXPECT_EQ(thrown_message([&] { survival_fragment(frag, "mai", {}); }),
              "SPIR-V: the module has no Fragment entry point named \"mai\"");
    const std::vector<uint32_t> vertex =
        compile(ds::shader::testing::kVertex, ds::shader::Stage::Vertex);
    EXPECT_EQ(thrown_message([&] { survival_fragment(vertex, "main", {}); }),
              "SPIR-V: the module has no Fragment entry point named \"main\"");
    EXPECT_EQ(thrown_message([&] { survival_fragment(frag, "main", {.zpixel_binding = 3}); }),
              "SPIR-V survival: the draw, z-pixel and record buffers need different bindings");
    EXPECT_EQ(thrown_message([&] { survival_fragment(frag, "main", {.draw_binding = 3}); }),
              "SPIR-V survival: the draw, z-pixel and record buffers need different bindings");
    const std::vector<uint32_t> set7 = compile(
        fragment("layout(set = 7, binding = 3) uniform U { vec4 tint; };", "color *= tint;"));
    EXPECT_EQ(thrown_message([&] { survival_fragment(set7, "main", {}); }),
              "SPIR-V: the module already uses descriptor set 7, the set the survival buffers "
              "need");
    EXPECT_NO_THROW(survival_fragment(set7, "main", {.set = 6}));
    EXPECT_EQ(
        thrown_message([&] { survival_fragment(frag, "main", {}, {.instance_location = 0}); }),
        "SPIR-V: the fragment shader already has an input at Location 0, the instance's");
    const std::vector<uint32_t> garbage{1, 2, 3, 4, 5, 6, 7};
    EXPECT_EQ(thrown_message([&] { survival_fragment(garbage, "main", {}); }),
              "SPIR-V: not a module (bad magic number or header)");
    std::vector<uint32_t> unended = frag;
    unended.pop_back();  // OpFunctionEnd
    EXPECT_EQ(thrown_message([&] { survival_fragment(unended, "main", {}); }),
              "SPIR-V: the last function has no OpFunctionEnd");
}

TEST_F(SurvivalModuleTest, ReadsInputAttachments) {
    const std::vector<uint32_t> subpass = compile(
        fragment("layout(input_attachment_index = 0, set = 0, binding = 0) uniform subpassInput s;",
                 "color *= subpassLoad(s);"));
    EXPECT_TRUE(reads_input_attachments(subpass));
    EXPECT_FALSE(reads_input_attachments(compile(fragment("", ""))));
    EXPECT_FALSE(reads_input_attachments(compile(fragment(
        "layout(set = 0, binding = 0) uniform sampler2D t;", "color *= texture(t, uv);"))));
    const std::vector<uint32_t> garbage{1, 2, 3, 4, 5, 6, 7};
    EXPECT_NE(thrown_message([&] { reads_input_attachments(garbage); }), "");
}

}  // namespace
}  // namespace ds::layer
