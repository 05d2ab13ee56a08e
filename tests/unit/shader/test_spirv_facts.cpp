// The SPIR-V reader behind each pipeline's early-Z verdict, on fragment shaders compiled here
// with the project's own compiler: every reason a shader loses early fragment tests, the
// execution mode that keeps them, and no false alarm from ordinary reads and local stores.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "renderer/spirv/spirv_facts.h"
#include "shader_test_fixture.h"

namespace ds::shader {
namespace {

using spirv::early_z_verdict;
using spirv::FragmentFacts;
using spirv::read_fragment_facts;

class SpirvFactsTest : public testing::ShaderTest {
  protected:
    // `body` inside main(), `decl` before it; one colour output.
    std::vector<uint32_t> fragment(const std::string& decl, const std::string& body) {
        write("f.frag", "#version 460\n" + decl +
                            "\nlayout(location = 0) out vec4 color;\n"
                            "layout(location = 0) in vec2 uv;\n"
                            "void main() {\n  color = vec4(uv, 0.0, 1.0);\n" +
                            body + "\n}\n");
        return Compiler(root(), cache()).compile("f.frag", Stage::Fragment).spirv;
    }
    std::string verdict(const std::string& decl, const std::string& body, bool a2c = false) {
        return early_z_verdict(fragment(decl, body), a2c);
    }
};

constexpr const char* kEarly = "layout(early_fragment_tests) in;";
constexpr const char* kImage = "layout(set = 0, binding = 0, r32ui) uniform uimage2D counts;";
constexpr const char* kBuffer = "layout(set = 0, binding = 1, std430) buffer B { uint n[]; } b;";

TEST_F(SpirvFactsTest, PlainShaderIsGuaranteed) {
    const std::string decl = "layout(set = 0, binding = 2) uniform sampler2D tex;";
    // A texture read, a uniform-less local array written and read: no side effects.
    EXPECT_EQ(verdict(decl,
                      "float a[2] = float[2](0.0, 1.0); a[int(uv.x)] = 2.0;\n"
                      "color *= texture(tex, uv) * a[1];"),
              "guaranteed");
    const FragmentFacts f = read_fragment_facts(fragment("", ""));
    EXPECT_FALSE(f.early_fragment_tests || f.discards || f.writes_depth || f.storage_writes ||
                 f.writes_sample_mask);
}

TEST_F(SpirvFactsTest, DiscardLosesEarlyZ) {
    EXPECT_EQ(verdict("", "if (uv.x < 0.5) discard;"), "lost: discard");
    EXPECT_TRUE(read_fragment_facts(fragment("", "if (uv.x < 0.5) discard;")).discards);
}

TEST_F(SpirvFactsTest, DemoteLosesEarlyZ) {
    EXPECT_EQ(verdict("#extension GL_EXT_demote_to_helper_invocation : require",
                      "if (uv.x < 0.5) demote;"),
              "lost: discard");
}

TEST_F(SpirvFactsTest, EarlyFragmentTestsKeepItWithDiscardOrDepthWrite) {
    EXPECT_EQ(verdict(kEarly, "if (uv.x < 0.5) discard;"), "guaranteed");
    EXPECT_TRUE(read_fragment_facts(fragment(kEarly, "")).early_fragment_tests);
    EXPECT_EQ(verdict(kEarly, "gl_FragDepth = 0.5;"), "guaranteed");
}

TEST_F(SpirvFactsTest, DepthWriteLosesEarlyZ) {
    EXPECT_EQ(verdict("", "gl_FragDepth = uv.x;"), "lost: depth write");
    const FragmentFacts f = read_fragment_facts(fragment("", "gl_FragDepth = uv.x;"));
    EXPECT_TRUE(f.writes_depth);
    EXPECT_TRUE(f.depth_replacing);
}

TEST_F(SpirvFactsTest, SampleMaskWriteLosesEarlyZ) {
    // Through an access chain into the gl_SampleMask array.
    EXPECT_EQ(verdict("", "gl_SampleMask[0] = 1;"), "lost: sample mask write");
}

TEST_F(SpirvFactsTest, StorageWritesLoseEarlyZWithoutEarlyTests) {
    EXPECT_EQ(verdict(kImage, "imageStore(counts, ivec2(0), uvec4(1u));"), "lost: storage writes");
    EXPECT_EQ(verdict(kImage, "imageAtomicAdd(counts, ivec2(gl_FragCoord.xy), 1u);"),
              "lost: storage writes");
    EXPECT_EQ(verdict(kBuffer, "atomicAdd(b.n[1], 1u);"), "lost: storage writes");
    EXPECT_EQ(verdict(kBuffer, "b.n[int(uv.x)] = 3u;"), "lost: storage writes");
    // Reading storage is no side effect.
    EXPECT_EQ(verdict(kBuffer, "color.x += float(b.n[0]);"), "guaranteed");
    EXPECT_EQ(verdict(std::string(kEarly) + kImage,
                      "imageAtomicAdd(counts, ivec2(gl_FragCoord.xy), 1u);"),
              "guaranteed");
}

TEST_F(SpirvFactsTest, ReasonsComeInAFixedOrder) {
    EXPECT_EQ(verdict(kBuffer,
                      "atomicAdd(b.n[0], 1u); if (uv.x < 0.5) discard;\n"
                      "gl_FragDepth = uv.y;",
                      /*a2c=*/true),
              "lost: depth write, discard, storage writes, alpha to coverage");
}

TEST_F(SpirvFactsTest, AlphaToCoverageIsPipelineState) {
    EXPECT_EQ(verdict("", "", /*a2c=*/true), "lost: alpha to coverage");
    EXPECT_EQ(verdict(kEarly, "", /*a2c=*/true), "guaranteed");
}

TEST_F(SpirvFactsTest, NoFragmentShaderIsGuaranteedAndGarbageIsRefused) {
    EXPECT_EQ(early_z_verdict(std::vector<uint32_t>{}, false), "guaranteed");
    const std::vector<uint32_t> garbage = {1, 2, 3, 4, 5, 6};
    EXPECT_THROW(read_fragment_facts(garbage), ds::Error);
    write("v.vert", "#version 460\nvoid main() { gl_Position = vec4(0.0); }\n");
    const std::vector<uint32_t> vert =
        Compiler(root(), cache()).compile("v.vert", Stage::Vertex).spirv;
    EXPECT_THROW(read_fragment_facts(vert), ds::Error);
}

}  // namespace
}  // namespace ds::shader
