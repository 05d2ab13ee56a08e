// The vertex shader's instance output (layer/spirv/instance_output.h): its location after every
// location the user outputs use, Flat uint, gl_InstanceIndex reused or added, and the pair with
// the survival fragment shader (survival.h) reading it at the same location. Every module made
// passes SPIRV-Tools' validator.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "instrument_test_fixture.h"
#include "layer/spirv/instance_output.h"
#include "layer/spirv/survival.h"
#include "measure_test_reader.h"

namespace ds::layer {
namespace {

using testing::count;
using testing::count_decorations;
using testing::InterfaceReader;
using testing::thrown_message;

class InstanceOutputTest : public testing::InstrumentTest {
  protected:
    // add_instance_output on `in` with the checks: valid, the output Flat u32 at its location
    // and stored once, one InstanceIndex.
    InstanceOutput add(std::span<const uint32_t> in) {
        EXPECT_EQ(testing::validation_errors(in), "") << "the input is not valid";
        InstanceOutput r = add_instance_output(in, "main");
        dump(r.spirv);
        EXPECT_EQ(testing::validation_errors(r.spirv), "");
        EXPECT_EQ(r.spirv.at(1), in[1]);
        const auto outputs = InterfaceReader(r.spirv).user_variables(spv::ExecutionModelVertex,
                                                                     spv::StorageClassOutput);
        const std::string key = std::to_string(r.location) + ".0";
        EXPECT_EQ(outputs.count(key), 1u) << key;
        if (outputs.count(key)) {
            EXPECT_EQ(outputs.at(key).type, "u32");
            EXPECT_TRUE(outputs.at(key).flat);
        }
        EXPECT_EQ(count(r.spirv, spv::OpStore), count(in, spv::OpStore) + 1);
        EXPECT_EQ(count_decorations(r.spirv, spv::DecorationBuiltIn, spv::BuiltInInstanceIndex),
                  1u);
        return r;
    }
    std::vector<uint32_t> vertex(const std::string& decl, const std::string& body = "") {
        return compile("#version 460\n" + decl + "\nvoid main() {\n  gl_Position = vec4(0.0);\n" +
                           body + "\n}\n",
                       ds::shader::Stage::Vertex);
    }
};

TEST_F(InstanceOutputTest, LocationFollowsTheOutputs) {
    struct Case {
        const char* decl;
        uint32_t location;
    };
    const Case cases[] = {
        {"", 0},
        {"layout(location = 0) out vec4 a;", 1},
        {"layout(location = 0) out vec4 a; layout(location = 3) out float b;", 4},
        {"layout(location = 2) out vec4 a; layout(location = 0) out vec2 b;", 3},
        // 64-bit: a dvec4 takes two locations, a dvec2 one.
        {"layout(location = 3) out dvec4 d;", 5},
        {"layout(location = 3) out dvec2 d;", 4},
        {"layout(location = 0) out dvec3 d[2];", 4},
        {"layout(location = 1) out dmat2x3 m;", 5},
        // Matrices: their columns; arrays: length x element.
        {"layout(location = 2) out mat3 m;", 5},
        {"layout(location = 1) out vec4 v[3];", 4},
        {"layout(location = 0) out mat2 m[2]; layout(location = 4) out float f;", 5},
        // Structs and blocks: the sum of their members; member locations.
        {"struct S { vec4 a; mat2 b; }; layout(location = 1) out S s;", 4},
        {"layout(location = 2) out Data { vec3 n; vec2 t; } o;", 4},
        {"layout(location = 0) out Data { layout(location = 1) vec3 n; "
         "layout(location = 3) flat int id; } o;",
         4},
        {"layout(location = 0) out Data { layout(location = 6) vec3 n; "
         "layout(location = 2) mat2 m; } o;",
         7},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.decl);
        EXPECT_EQ(add(vertex(c.decl)).location, c.location);
    }
}

TEST_F(InstanceOutputTest, ExistingInstanceIndexIsReused) {
    const std::vector<uint32_t> in =
        vertex("layout(location = 0) flat out int i;", "i = gl_InstanceIndex * 2;");
    ASSERT_EQ(count_decorations(in, spv::DecorationBuiltIn, spv::BuiltInInstanceIndex), 1u);
    const InstanceOutput r = add(in);
    EXPECT_EQ(r.location, 1u);
    EXPECT_EQ(count(r.spirv, spv::OpVariable), count(in, spv::OpVariable) + 1);
    EXPECT_EQ(count(r.spirv, spv::OpBitcast), count(in, spv::OpBitcast) + 1);  // int to uint
}

TEST_F(InstanceOutputTest, MissingInstanceIndexIsAdded) {
    const std::vector<uint32_t> in = vertex("layout(location = 0) out vec4 a;");
    ASSERT_EQ(count_decorations(in, spv::DecorationBuiltIn, spv::BuiltInInstanceIndex), 0u);
    const InstanceOutput r = add(in);
    EXPECT_EQ(count(r.spirv, spv::OpVariable), count(in, spv::OpVariable) + 2);
}

TEST_F(InstanceOutputTest, EverySpirvVersion) {
    const std::string source =
        "#version 460\nlayout(location = 0) out vec4 a;\nlayout(location = 1) out vec2 b[2];\n"
        "void main() { gl_Position = vec4(0.0); a = vec4(1.0); b[0] = b[1] = vec2(0.5); }\n";
    for (const char* env :
         {"vulkan1.0", "vulkan1.1", "vulkan1.1 --target-env spirv1.4", "vulkan1.2", "vulkan1.3"}) {
        SCOPED_TRACE(env);
        EXPECT_EQ(add(compile_for(source, env, "", "t.vert")).location, 3u);
        EXPECT_EQ(add(compile_for(source, env, "-g", "t.vert")).location, 3u);
    }
}

TEST_F(InstanceOutputTest, StoreLeadsTheEntryFunction) {
    // After the locals of main's first block, before anything main does.
    const InstanceOutput r =
        add(vertex("layout(location = 0) out vec4 a;",
                   "vec4 t[2] = vec4[2](vec4(1.0), vec4(2.0)); a = t[gl_VertexIndex & 1];"));
    const std::vector<testing::Op> ops = testing::split(r.spirv);
    size_t label = 0, first_store = 0;
    for (size_t i = 0; i < ops.size() && !first_store; ++i) {
        if (ops[i].op == spv::OpLabel && !label) label = i;
        if (ops[i].op == spv::OpStore && label) first_store = i;
    }
    ASSERT_GT(first_store, label);
    for (size_t i = label + 1; i < first_store; ++i)
        EXPECT_TRUE(ops[i].op == spv::OpVariable || ops[i].op == spv::OpLoad ||
                    ops[i].op == spv::OpBitcast)
            << i;
}

TEST_F(InstanceOutputTest, PairsWithTheSurvivalShader) {
    // The vertex shader's new output and the survival shader's instance input: same location,
    // both Flat uint, and the fragment shader's other inputs untouched.
    const std::vector<uint32_t> vs =
        vertex("layout(location = 0) out vec2 uv;\nlayout(location = 1) out dvec4 d;",
               "uv = vec2(0.5); d = dvec4(1.0);");
    const InstanceOutput r = add(vs);
    ASSERT_EQ(r.location, 3u);
    const std::vector<uint32_t> fs =
        survival_fragment(compile(fragment("", "")), "main", {}, {.instance_location = r.location});
    dump(fs);
    EXPECT_EQ(testing::validation_errors(fs), "");
    const auto outputs =
        InterfaceReader(r.spirv).user_variables(spv::ExecutionModelVertex, spv::StorageClassOutput);
    const auto inputs =
        InterfaceReader(fs).user_variables(spv::ExecutionModelFragment, spv::StorageClassInput);
    ASSERT_TRUE(outputs.count("3.0") && inputs.count("3.0"));
    EXPECT_EQ(inputs.at("3.0").type, outputs.at("3.0").type);
    EXPECT_EQ(inputs.at("3.0").flat, outputs.at("3.0").flat);
    EXPECT_EQ(inputs.at("0.0").type, outputs.at("0.0").type);
}

TEST_F(InstanceOutputTest, Errors) {
    const std::vector<uint32_t> vs = vertex("");
    EXPECT_EQ(thrown_message([&] { add_instance_output(vs, "mai"); }),
              "SPIR-V: the module has no Vertex entry point named \"mai\"");
    const std::vector<uint32_t> fs = compile(fragment("", ""));
    EXPECT_EQ(thrown_message([&] { add_instance_output(fs, "main"); }),
              "SPIR-V: the module has no Vertex entry point named \"main\"");
    const std::vector<uint32_t> garbage{1, 2, 3, 4, 5, 6, 7};
    EXPECT_EQ(thrown_message([&] { add_instance_output(garbage, "main"); }),
              "SPIR-V: not a module (bad magic number or header)");
}

}  // namespace
}  // namespace ds::layer
