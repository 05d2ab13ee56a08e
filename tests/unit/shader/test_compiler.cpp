#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <thread>

#include "renderer/shader/compiler.h"
#include "tests/unit/shader/shader_test_fixture.h"

namespace ds::shader::testing {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

bool contains(const std::vector<std::filesystem::path>& files, const std::filesystem::path& f) {
    return std::find(files.begin(), files.end(), f) != files.end();
}

using CompilerTest = ShaderTest;

TEST_F(CompilerTest, CompilesEveryStageToSpirv) {
    write("a.vert", kVertex);
    write("a.frag", kIncludingFragment);
    write("common/inc.glsl", include_returning("2.0"));
    write("a.comp", kCompute);
    Compiler compiler(root(), cache());
    for (auto [file, stage] : {std::pair{"a.vert", Stage::Vertex},
                               {"a.frag", Stage::Fragment},
                               {"a.comp", Stage::Compute}}) {
        const CompileResult result = compiler.compile(file, stage);
        ASSERT_GE(result.spirv.size(), 5u) << file;
        EXPECT_EQ(result.spirv[0], 0x07230203u) << file;
        EXPECT_GE(result.spirv[1], 0x00010500u) << file;  // SPIR-V 1.5 or newer (Vulkan 1.3)
        EXPECT_FALSE(result.from_cache) << file;
        EXPECT_EQ(result.files.front(), root() / file) << file;
    }
    EXPECT_EQ(compiler.stats().compiles, 3u);
    EXPECT_EQ(compiler.stats().cache_hits, 0u);
}

TEST_F(CompilerTest, FilesListTheSourceAndEveryIncludeAbsolute) {
    write("main.frag", kIncludingFragment);
    write("common/inc.glsl", "#include \"nested.glsl\"\n" + include_returning("2.0"));
    write("common/nested.glsl", "// nothing\n");
    const CompileResult result = Compiler(root(), cache()).compile("main.frag", Stage::Fragment);
    ASSERT_EQ(result.files.size(), 3u);
    EXPECT_EQ(result.files[0], root() / "main.frag");
    EXPECT_TRUE(contains(result.files, root() / "common/inc.glsl"));
    EXPECT_TRUE(contains(result.files, root() / "common/nested.glsl"));
    for (const auto& file : result.files) EXPECT_TRUE(file.is_absolute()) << file;
}

TEST_F(CompilerTest, ErrorInTheMainFileNamesItsLine) {
    // Line 6 comes after an include, so this also checks the line count is restored after it.
    write("main.frag", R"(#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/inc.glsl"
layout(location = 0) out vec4 color;
void main() {
    color = vec4(not_declared);
}
)");
    write("common/inc.glsl", include_returning("2.0"));
    const std::string error = error_of([&] {
        Compiler(root(), cache()).compile("main.frag", Stage::Fragment, {{"SOME_DEFINE", "1"}});
    });
    EXPECT_THAT(error, StartsWith("main.frag:6: "));
    EXPECT_THAT(error, HasSubstr("'not_declared' : undeclared identifier"));
    EXPECT_THAT(error, ::testing::Not(HasSubstr("compilation terminated")));
    EXPECT_THAT(error, ::testing::Not(HasSubstr("ERROR")));
}

TEST_F(CompilerTest, ErrorInsideAnIncludeNamesTheInclude) {
    write("main.frag", kIncludingFragment);
    write("common/inc.glsl", "// line 1\n// line 2\nfloat scale(float x) { return x * oops; }\n");
    try {
        Compiler(root(), cache()).compile("main.frag", Stage::Fragment);
        FAIL() << "no ShaderError";
    } catch (const ShaderError& e) {
        EXPECT_THAT(e.what(), StartsWith("common/inc.glsl:3: 'oops' : undeclared identifier"));
        // A hot reloader keeps watching the broken include.
        EXPECT_TRUE(contains(e.files(), root() / "common/inc.glsl"));
        EXPECT_TRUE(contains(e.files(), root() / "main.frag"));
    }
}

TEST_F(CompilerTest, NestedIncludeResolvesNextToItsIncluder) {
    write("main.frag", kIncludingFragment);
    // "detail.glsl" exists only beside common/inc.glsl, not in the root.
    write("common/inc.glsl",
          "#include \"detail.glsl\"\nfloat scale(float x) { return helper(x); }\n");
    write("common/detail.glsl", "\nfloat helper(float x) { return x + missing_name; }\n");
    const std::string error =
        error_of([&] { Compiler(root(), cache()).compile("main.frag", Stage::Fragment); });
    EXPECT_THAT(error, StartsWith("common/detail.glsl:2: 'missing_name'"));
}

TEST_F(CompilerTest, MissingIncludeIsAnErrorNamingIt) {
    write("main.frag", R"(#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/missing.glsl"
void main() {}
)");
    const std::string error =
        error_of([&] { Compiler(root(), cache()).compile("main.frag", Stage::Fragment); });
    EXPECT_THAT(error, StartsWith("main.frag:3: "));
    EXPECT_THAT(error, HasSubstr("common/missing.glsl"));
    EXPECT_THAT(error, HasSubstr("cannot open include"));
}

TEST_F(CompilerTest, IncludeCycleIsAnError) {
    write("main.frag",
          "#version 460\n#extension GL_GOOGLE_include_directive : require\n"
          "#include \"common/a.glsl\"\nvoid main() {}\n");
    write("common/a.glsl", "// a\n#include \"b.glsl\"\n");
    write("common/b.glsl", "// b\n// b\n#include \"a.glsl\"\n");
    const std::string error =
        error_of([&] { Compiler(root(), cache()).compile("main.frag", Stage::Fragment); });
    EXPECT_THAT(error, StartsWith("common/b.glsl:3: "));
    EXPECT_THAT(error, HasSubstr("include cycle (main.frag -> common/a.glsl -> common/b.glsl -> "
                                 "common/a.glsl)"));
}

TEST_F(CompilerTest, GuardedIncludeTwiceIsFine) {
    write("main.frag", R"(#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/inc.glsl"
#include "common/inc.glsl"
layout(location = 0) out vec4 color;
void main() { color = vec4(scale(1.0)); }
)");
    write("common/inc.glsl", include_returning("2.0"));
    EXPECT_FALSE(Compiler(root(), cache()).compile("main.frag", Stage::Fragment).spirv.empty());
}

TEST_F(CompilerTest, MissingSourceCannotOpen) {
    const std::string error =
        error_of([&] { Compiler(root(), cache()).compile("nope.frag", Stage::Fragment); });
    EXPECT_EQ(error, "nope.frag: cannot open");
}

TEST_F(CompilerTest, WrongStageIsALinkOrParseError) {
    write("main.comp", kVertex);  // a vertex shader given as compute: no local size, bad input
    const std::string error =
        error_of([&] { Compiler(root(), cache()).compile("main.comp", Stage::Compute); });
    EXPECT_THAT(error, StartsWith("main.comp:"));
}

TEST_F(CompilerTest, DefinesReachTheSourceAndKeepLineNumbers) {
    write("main.frag", R"(#version 460
layout(location = 0) out vec4 color;
void main() {
#if defined(BROKEN)
    color = vec4(broken_here);
#else
    color = vec4(VALUE);
#endif
}
)");
    Compiler compiler(root(), cache());
    const auto a = compiler.compile("main.frag", Stage::Fragment, {{"VALUE", "0.25"}});
    const auto b = compiler.compile("main.frag", Stage::Fragment, {{"VALUE", "0.75"}});
    EXPECT_NE(a.spirv, b.spirv);
    const std::string error = error_of([&] {
        compiler.compile("main.frag", Stage::Fragment, {{"BROKEN", ""}, {"VALUE", "1.0"}});
    });
    EXPECT_THAT(error, StartsWith("main.frag:5: 'broken_here'"));
}

TEST_F(CompilerTest, BadDefineNameIsAnError) {
    write("main.frag", "#version 460\nvoid main() {}\n");
    Compiler compiler(root(), cache());
    EXPECT_THAT(error_of([&] {
                    compiler.compile("main.frag", Stage::Fragment, {{"1BAD", ""}});
                }),
                HasSubstr("bad define name '1BAD'"));
    EXPECT_THAT(error_of([&] {
                    compiler.compile("main.frag", Stage::Fragment, {{"OK", "1\n#error x"}});
                }),
                HasSubstr("line break"));
}

TEST_F(CompilerTest, SeparateCompilersRunConcurrently) {
    write("a.comp", kCompute);
    write("b.frag", kIncludingFragment);
    write("common/inc.glsl", include_returning("3.0"));
    std::vector<uint32_t> first, second;
    std::thread t1([&] {
        Compiler c(root(), dir_ / "cache1");
        for (int i = 0; i < 5; ++i) first = c.compile("a.comp", Stage::Compute).spirv;
    });
    std::thread t2([&] {
        Compiler c(root(), std::filesystem::path{});  // no disk cache: really compiles 5 times
        for (int i = 0; i < 5; ++i) second = c.compile("b.frag", Stage::Fragment).spirv;
    });
    t1.join();
    t2.join();
    ASSERT_FALSE(first.empty());
    ASSERT_FALSE(second.empty());
    EXPECT_EQ(first[0], 0x07230203u);
    EXPECT_EQ(second[0], 0x07230203u);
}

}  // namespace
}  // namespace ds::shader::testing
