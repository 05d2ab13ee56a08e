// The measurement draw's fragment shader (layer/spirv/measure.h): for every stage, each user
// output has an Input at its location and component with the same type structure, integer and
// double ones Flat; no outputs; two atomics. Every module made passes SPIRV-Tools' validator
// (Vulkan environment of its SPIR-V version).
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "instrument_test_fixture.h"
#include "layer/spirv/measure.h"
#include "measure_test_reader.h"

namespace ds::layer {
namespace {

using testing::count;
using testing::interface_of;
using testing::InterfaceReader;
using testing::thrown_message;
using testing::Variable;
using Variables = std::map<std::string, Variable>;

class MeasureFragmentTest : public testing::InstrumentTest {
  protected:
    // measurement_fragment on `stage` (an entry of `model`), with the structural checks; the
    // fragment shader's user inputs.
    Variables measure(std::span<const uint32_t> stage,
                      spv::ExecutionModel model = spv::ExecutionModelVertex,
                      const CounterBindings& b = {}, const std::string& entry = "main") {
        EXPECT_EQ(testing::validation_errors(stage), "") << "the input is not valid";
        fs_ = measurement_fragment(stage, entry, b);
        dump(fs_);
        EXPECT_EQ(testing::validation_errors(fs_), "");
        EXPECT_EQ(fs_.at(1), std::max(stage[1], 0x10000u));  // SPIR-V version
        const InterfaceReader out(stage), in(fs_);
        const Variables outputs = out.user_variables(model, spv::StorageClassOutput);
        const Variables inputs =
            in.user_variables(spv::ExecutionModelFragment, spv::StorageClassInput);
        EXPECT_EQ(types_of(inputs), types_of(outputs));
        for (const auto& [key, v] : inputs) EXPECT_TRUE(v.flat_ok) << key << " " << v.type;
        EXPECT_EQ(in.variables(spv::StorageClassOutput), 0u);
        EXPECT_EQ(count(fs_, spv::OpAtomicIAdd), 2u);
        EXPECT_EQ(testing::bindings_in_set(fs_, b.set),
                  (std::vector<uint32_t>{std::min(b.draw_binding, b.pixel_binding),
                                         std::max(b.draw_binding, b.pixel_binding)}));
        return inputs;
    }
    std::vector<uint32_t> vertex(const std::string& decl, const std::string& body = "") {
        return compile("#version 460\n" + decl + "\nvoid main() {\n" + body + "\n}\n",
                       ds::shader::Stage::Vertex);
    }
    static std::map<std::string, std::string> types_of(const Variables& v) {
        std::map<std::string, std::string> out;
        for (const auto& [key, var] : v) out[key] = var.type;
        return out;
    }
    bool has_capability(spv::Capability c) const {
        const std::vector<uint32_t> caps = InterfaceReader(fs_).capabilities();
        return std::find(caps.begin(), caps.end(), uint32_t(c)) != caps.end();
    }

    std::vector<uint32_t> fs_;  // the last measurement shader
};

constexpr const char* kBasicOutputs = R"(
layout(location = 0) out vec2 a;
layout(location = 1) out vec3 b;
layout(location = 2) out vec4 c;
layout(location = 3) out float d;
layout(location = 4) flat out int e;
layout(location = 5) flat out uint f;
layout(location = 6) flat out ivec3 g;
layout(location = 7) out mat3 h;
layout(location = 10) out mat2x4 k;
)";

TEST_F(MeasureFragmentTest, BasicTypes) {
    const Variables in = measure(vertex(kBasicOutputs, "gl_Position = vec4(0.0);"));
    const std::map<std::string, std::string> expected{
        {"0.0", "v2<f32>"}, {"1.0", "v3<f32>"},     {"2.0", "v4<f32>"},
        {"3.0", "f32"},     {"4.0", "i32"},         {"5.0", "u32"},
        {"6.0", "v3<i32>"}, {"7.0", "m3<v3<f32>>"}, {"10.0", "m2<v4<f32>>"}};
    EXPECT_EQ(types_of(in), expected);
    for (const auto& [key, v] : in)
        EXPECT_EQ(v.flat, key == "4.0" || key == "5.0" || key == "6.0") << key;
    EXPECT_FALSE(has_capability(spv::CapabilityFloat64));
    EXPECT_EQ(InterfaceReader(fs_).capabilities(), std::vector<uint32_t>{spv::CapabilityShader});
}

TEST_F(MeasureFragmentTest, OutputArray) {
    const Variables in =
        measure(vertex("layout(location = 3) out vec4 v[2];\n"
                       "layout(location = 5) flat out uint u[3];"));
    EXPECT_EQ(types_of(in),
              (std::map<std::string, std::string>{{"3.0", "[2]v4<f32>"}, {"5.0", "[3]u32"}}));
    EXPECT_TRUE(in.at("5.0").flat);
    EXPECT_FALSE(in.at("3.0").flat);
}

TEST_F(MeasureFragmentTest, SpecConstantArrayLengthKeepsItsSpecId) {
    const Variables in =
        measure(vertex("layout(constant_id = 3) const int N = 2;\n"
                       "layout(location = 0) out vec4 v[N];",
                       "for (int i = 0; i < N; ++i) v[i] = vec4(i);"));
    EXPECT_EQ(in.at("0.0").type, "[spec3=2]v4<f32>");
}

TEST_F(MeasureFragmentTest, OutputBlock) {
    const Variables in =
        measure(vertex("layout(location = 0) out Data { vec3 n; flat uint id; } o;",
                       "o.n = vec3(1.0); o.id = 3u;"));
    EXPECT_EQ(types_of(in), (std::map<std::string, std::string>{{"0.0", "block{v3<f32>;u32;}"}}));
    EXPECT_FALSE(in.at("0.0").flat);  // on the member
    // Member locations, and a struct that is not a block.
    const Variables members = measure(vertex(R"(
layout(location = 0) out Data { layout(location = 4) vec3 n; layout(location = 6) flat int id; } o;
struct S { int a; float b; dvec2 c; };
layout(location = 8) out S s;)"));
    EXPECT_EQ(types_of(members),
              (std::map<std::string, std::string>{{"0.0", "block{v3<f32> @4;i32 @6;}"},
                                                  {"8.0", "struct{i32;f32;v2<f64>;}"}}));
    EXPECT_TRUE(has_capability(spv::CapabilityFloat64));
}

TEST_F(MeasureFragmentTest, DoubleNeedsFloat64AndFlat) {
    const Variables in =
        measure(vertex("layout(location = 0) out vec4 c;\n"
                       "layout(location = 1) flat out dvec2 d;",
                       "c = vec4(1.0); d = dvec2(2.0);"));
    EXPECT_EQ(in.at("1.0").type, "v2<f64>");
    EXPECT_TRUE(in.at("1.0").flat);
    EXPECT_FALSE(in.at("0.0").flat);
    EXPECT_TRUE(has_capability(spv::CapabilityFloat64));
}

TEST_F(MeasureFragmentTest, SixteenAndSixtyFourBitIntegersCarryTheirCapabilities) {
    const std::string source = R"(#version 450
#extension GL_EXT_shader_explicit_arithmetic_types : require
layout(location = 0) out float16_t h;
layout(location = 1) flat out i16vec2 s;
layout(location = 2) flat out int64_t l;
void main() { gl_Position = vec4(0); h = float16_t(1); s = i16vec2(1); l = 1l; }
)";
    for (const char* env : {"vulkan1.0", "vulkan1.2"}) {
        SCOPED_TRACE(env);
        const Variables in = measure(compile_for(source, env, "", "t.vert"));
        EXPECT_EQ(types_of(in), (std::map<std::string, std::string>{
                                    {"0.0", "f16"}, {"1.0", "v2<i16>"}, {"2.0", "i64"}}));
        for (spv::Capability c : {spv::CapabilityStorageInputOutput16, spv::CapabilityInt64,
                                  spv::CapabilityInt16, spv::CapabilityFloat16})
            EXPECT_TRUE(has_capability(c)) << c;
    }
}

TEST_F(MeasureFragmentTest, Components) {
    const Variables in =
        measure(vertex("layout(location = 1) out vec2 c0;\n"
                       "layout(location = 1, component = 2) out vec2 c;\n"
                       "layout(location = 2, component = 3) flat out int i;"));
    EXPECT_EQ(types_of(in), (std::map<std::string, std::string>{
                                {"1.0", "v2<f32>"}, {"1.2", "v2<f32>"}, {"2.3", "i32"}}));
}

TEST_F(MeasureFragmentTest, NoUserOutputs) {
    // Nothing at all, then gl_PerVertex only (with gl_PointSize and a clip distance too).
    for (const char* body : {"",
                             "gl_Position = vec4(1.0); gl_PointSize = 2.0;\n"
                             "gl_ClipDistance[0] = 0.5;"}) {
        SCOPED_TRACE(body);
        const std::vector<uint32_t> vs = vertex("out float gl_ClipDistance[1];", body);
        EXPECT_TRUE(measure(vs).empty());
        EXPECT_EQ(interface_of(fs_, "main").size(), 3u);  // SPIR-V 1.5: FragCoord and buffers
        EXPECT_EQ(InterfaceReader(fs_).variables(spv::StorageClassInput), 1u);  // FragCoord
    }
}

TEST_F(MeasureFragmentTest, TessellationEvaluation) {
    const std::string source = R"(#version 450
layout(triangles, equal_spacing, ccw) in;
layout(location = 0) in vec3 in_normal[];
layout(location = 0) out vec3 normal;
layout(location = 1) flat out int patch_id;
layout(location = 2) out Extra { vec2 uv; } extra;
void main() {
    gl_Position = vec4(gl_TessCoord, 1.0);
    normal = in_normal[0];
    patch_id = gl_PrimitiveID;
    extra.uv = gl_TessCoord.xy;
}
)";
    const Variables in = measure(compile_for(source, "vulkan1.2", "", "t.tese"),
                                 spv::ExecutionModelTessellationEvaluation);
    EXPECT_EQ(types_of(in), (std::map<std::string, std::string>{
                                {"0.0", "v3<f32>"}, {"1.0", "i32"}, {"2.0", "block{v2<f32>;}"}}));
}

TEST_F(MeasureFragmentTest, Geometry) {
    const std::string source = R"(#version 450
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
layout(location = 0) in vec2 in_uv[];
layout(location = 0) out vec2 uv;
layout(location = 1) flat out uvec2 ids;
void main() {
    for (int i = 0; i < 3; ++i) {
        gl_Position = gl_in[i].gl_Position;
        gl_Layer = 1;
        uv = in_uv[i];
        ids = uvec2(gl_PrimitiveIDIn, i);
        EmitVertex();
    }
}
)";
    for (const char* env : {"vulkan1.0", "vulkan1.3"}) {
        SCOPED_TRACE(env);
        const Variables in =
            measure(compile_for(source, env, "", "t.geom"), spv::ExecutionModelGeometry);
        EXPECT_EQ(types_of(in),
                  (std::map<std::string, std::string>{{"0.0", "v2<f32>"}, {"1.0", "v2<u32>"}}));
    }
}

TEST_F(MeasureFragmentTest, EverySpirvVersion) {
    const std::string source = std::string("#version 450\n") + kBasicOutputs +
                               "layout(location = 12) out Data { vec3 n; flat uint id; } o;\n"
                               "void main() { gl_Position = vec4(0.0); }\n";
    struct Case {
        const char* env;
        uint32_t version;
    };
    for (const Case& c : {Case{"vulkan1.0", 0x10000}, Case{"vulkan1.1", 0x10300},
                          Case{"vulkan1.1 --target-env spirv1.4", 0x10400},
                          Case{"vulkan1.2", 0x10500}, Case{"vulkan1.3", 0x10600}}) {
        SCOPED_TRACE(c.env);
        const std::vector<uint32_t> vs = compile_for(source, c.env, "", "t.vert");
        ASSERT_GT(vs.size(), 5u);
        ASSERT_EQ(vs[1], c.version);
        EXPECT_EQ(measure(vs).size(), 10u);
        // Below 1.3 the StorageBuffer class needs its extension; before 1.4 only Input and
        // Output variables are in the interface (here the inputs and FragCoord).
        EXPECT_EQ(count(fs_, spv::OpExtension), c.version < 0x10300 ? 1u : 0u);
        EXPECT_EQ(interface_of(fs_, "main").size(), 11u + (c.version < 0x10400 ? 0 : 2));
    }
}

TEST_F(MeasureFragmentTest, DepthscopesOwnVertexShaders) {
    struct Real {
        const char* file;
        std::vector<ds::shader::Define> defines;
        size_t inputs;
    };
    ds::shader::Compiler compiler(ds::shader::Compiler::default_shader_root(), "");
    const Real shaders[] = {
        {"forward.vert", {}, 4},
        {"forward.vert", {{"NON_INVARIANT", "1"}}, 4},
        {"depth_prepass.vert", {}, 4},
        {"depth_prepass.vert", {{"SCENE_VARYINGS", "0"}}, 0},
        {"depth_prepass.vert", {{"SCENE_VARYINGS", "1"}, {"SURFACE_ID", "1"}}, 2},
        {"forward.vert", {{"PIXEL_HISTORY", "1"}}, 5},
        {"shadow.vert", {}, 1},
        {"transparent.vert", {}, 4},
        {"fullscreen.vert", {}, 1},
    };
    for (const Real& s : shaders) {
        SCOPED_TRACE(std::string(s.file) + (s.defines.empty() ? "" : " " + s.defines[0].name));
        const Variables in =
            measure(compiler.compile(s.file, ds::shader::Stage::Vertex, s.defines).spirv);
        EXPECT_EQ(in.size(), s.inputs);
    }
}

// The uint constant values of the OpAccessChain indices into the variable `base`, in order.
std::vector<uint32_t> indices_into(const std::vector<uint32_t>& spirv, uint32_t base) {
    std::map<uint32_t, uint32_t> constants;
    std::vector<uint32_t> out;
    for (const testing::Op& o : testing::split(spirv)) {
        if (o.op == spv::OpConstant) constants[o.operands[1]] = o.operands[2];
        if (o.op != spv::OpAccessChain || o.operands[2] != base) continue;
        for (size_t i = 3; i < o.operands.size(); ++i) {
            const auto it = constants.find(o.operands[i]);
            out.push_back(it == constants.end() ? UINT32_MAX : it->second);  // UINT32_MAX: computed
        }
    }
    return out;
}

TEST_F(MeasureFragmentTest, CountsIntoTheRasterizedSlot) {
    measure(vertex("layout(location = 0) out vec4 c;"), spv::ExecutionModelVertex,
            {.set = 2, .draw_binding = 4, .pixel_binding = 9});
    uint32_t draw = 0, pixel = 0;
    for (const testing::Op& o : testing::split(fs_))
        if (o.op == spv::OpDecorate && o.operands[1] == spv::DecorationBinding)
            (o.operands[2] == 4 ? draw : pixel) = o.operands[0];
    // DrawCounters.rasterized (member 2); PixelCounters width, height, counts[index].
    EXPECT_EQ(indices_into(fs_, draw), std::vector<uint32_t>{2});
    EXPECT_EQ(indices_into(fs_, pixel), (std::vector<uint32_t>{0, 1, 4, UINT32_MAX}));
    // index = select(inside, (y * width + x) * 4 + 2, 0).
    std::map<uint32_t, uint32_t> constants;
    size_t plus_two = 0;
    for (const testing::Op& o : testing::split(fs_)) {
        if (o.op == spv::OpConstant) constants[o.operands[1]] = o.operands[2];
        plus_two += o.op == spv::OpIAdd && constants.contains(o.operands[3]) &&
                    constants[o.operands[3]] == 2;
    }
    EXPECT_EQ(plus_two, 1u);
    EXPECT_EQ(count(fs_, spv::OpSelect), 2u);
    EXPECT_EQ(count(fs_, spv::OpKill), 0u);
}

TEST_F(MeasureFragmentTest, BindingsAreTheCallers) {
    measure(vertex("layout(location = 0) out vec4 c;"), spv::ExecutionModelVertex,
            {.set = 3, .draw_binding = 5, .pixel_binding = 2});
    EXPECT_TRUE(testing::bindings_in_set(fs_, 7).empty());
}

// A Vertex entry "v" and a Fragment entry "main", each with an output of its own, and a
// Vertex entry "w" that shares v's output.
constexpr const char* kThreeEntries = R"(
OpCapability Shader
OpMemoryModel Logical GLSL450
OpEntryPoint Vertex %v "v" %vout
OpEntryPoint Vertex %w "w" %vout %wout
OpEntryPoint Fragment %f "main" %fout
OpExecutionMode %f OriginUpperLeft
OpDecorate %vout Location 0
OpDecorate %wout Location 1
OpDecorate %fout Location 0
%void = OpTypeVoid
%fn = OpTypeFunction %void
%float = OpTypeFloat 32
%v4 = OpTypeVector %float 4
%ptr_out = OpTypePointer Output %v4
%vout = OpVariable %ptr_out Output
%wout = OpVariable %ptr_out Output
%fout = OpVariable %ptr_out Output
%v = OpFunction %void None %fn
%v0 = OpLabel
OpReturn
OpFunctionEnd
%w = OpFunction %void None %fn
%w0 = OpLabel
OpReturn
OpFunctionEnd
%f = OpFunction %void None %fn
%f0 = OpLabel
OpReturn
OpFunctionEnd
)";

TEST_F(MeasureFragmentTest, OnlyTheNamedEntrysOutputs) {
    const std::vector<uint32_t> module = testing::assemble(kThreeEntries, 0x10300);
    EXPECT_EQ(types_of(measure(module, spv::ExecutionModelVertex, {}, "v")),
              (std::map<std::string, std::string>{{"0.0", "v4<f32>"}}));
    // "w" is the reader's second Vertex entry: compared by hand.
    const Variables w = InterfaceReader(measurement_fragment(module, "w", {}))
                            .user_variables(spv::ExecutionModelFragment, spv::StorageClassInput);
    EXPECT_EQ(types_of(w),
              (std::map<std::string, std::string>{{"0.0", "v4<f32>"}, {"1.0", "v4<f32>"}}));
    EXPECT_EQ(thrown_message([&] { measurement_fragment(module, "main", {}); }),
              "SPIR-V: the module has no Vertex, TessellationEvaluation or Geometry entry point "
              "named \"main\"");
}

TEST_F(MeasureFragmentTest, FragmentOnlyModuleThrows) {
    const std::vector<uint32_t> frag = compile(fragment("", ""));
    EXPECT_EQ(thrown_message([&] { measurement_fragment(frag, "main", {}); }),
              "SPIR-V: the module has no Vertex, TessellationEvaluation or Geometry entry point "
              "named \"main\"");
    const std::vector<uint32_t> vs = vertex("");
    EXPECT_NE(thrown_message([&] { measurement_fragment(vs, "mai", {}); }), "");
}

TEST_F(MeasureFragmentTest, GarbageThrows) {
    const std::vector<uint32_t> garbage{1, 2, 3, 4, 5, 6, 7};
    EXPECT_EQ(thrown_message([&] { measurement_fragment(garbage, "main", {}); }),
              "SPIR-V: not a module (bad magic number or header)");
    EXPECT_NE(thrown_message([&] { measurement_fragment({}, "main", {}); }), "");
    std::vector<uint32_t> truncated = vertex("layout(location = 0) out vec4 c;");
    truncated.back() = 2u << spv::WordCountShift | spv::OpFunctionEnd;
    EXPECT_NE(
        thrown_message([&] { measurement_fragment(truncated, "main", {}); }).find("truncated"),
        std::string::npos);
    // An interface id that names nothing.
    std::string text = kThreeEntries;
    text.replace(text.find("%vout %wout"), 11, "%vout %fn");
    EXPECT_EQ(
        thrown_message([&] { measurement_fragment(testing::assemble(text, 0x10300), "w", {}); }),
        "SPIR-V: an entry point's interface lists a non-variable");
}

TEST_F(MeasureFragmentTest, EqualBindingsThrow) {
    EXPECT_EQ(
        thrown_message([&] { measurement_fragment(vertex(""), "main", {.draw_binding = 1}); }),
        "SPIR-V measure: the draw and pixel counters need different bindings");
}

}  // namespace
}  // namespace ds::layer
