#include <gtest/gtest.h>

#include "renderer/shader/diagnostics.h"
#include "renderer/shader/source_tree.h"

namespace ds::shader {
namespace {

TEST(FormatInfoLog, KeepsErrorsWithTheirFileAndLine) {
    const char* log =
        "WARNING: main.frag:2: '' : some warning\n"
        "ERROR: common/brdf.glsl:12: 'foo' : undeclared identifier \n"
        "ERROR: main.frag:4: '' : compilation terminated \n"
        "ERROR: 2 compilation errors.  No code generated.\n\n";
    EXPECT_EQ(format_info_log(log, "main.frag"),
              "common/brdf.glsl:12: 'foo' : undeclared identifier");
}

TEST(FormatInfoLog, MessagesWithoutALocationGoToTheMainFile) {
    EXPECT_EQ(format_info_log("ERROR: Linking fragment stage: Missing entry point: Each stage "
                              "requires one entry point\n",
                              "a.frag"),
              "a.frag: Linking fragment stage: Missing entry point: Each stage requires one "
              "entry point");
}

TEST(FormatInfoLog, UnnamedStringsAreTheDefines) {
    EXPECT_EQ(format_info_log("ERROR: 0:1: 'X' : Macro redefined\n", "a.frag"),
              "<defines>:1: 'X' : Macro redefined");
}

TEST(FormatInfoLog, KeepsSeveralErrorsOncePerLine) {
    const char* log =
        "ERROR: a.frag:3: 'x' : undeclared identifier\n"
        "ERROR: a.frag:3: 'x' : undeclared identifier\n"
        "ERROR: common/c.glsl:7: 'y' : syntax error\n";
    EXPECT_EQ(format_info_log(log, "a.frag"),
              "a.frag:3: 'x' : undeclared identifier\ncommon/c.glsl:7: 'y' : syntax error");
}

TEST(FormatInfoLog, NeverEmpty) {
    EXPECT_EQ(format_info_log("", "a.frag"), "a.frag: compilation failed");
    EXPECT_EQ(format_info_log("odd text\n", "a.frag"), "a.frag: compilation failed (odd text)");
}

TEST(ScanIncludes, FindsQuotedAndAngledIncludes) {
    const auto includes = scan_includes(
        "#version 460\n  #  include \"common/a.glsl\"\n#include <b.glsl>\n"
        "// not #include \"c.glsl\"\n#includes \"no\"\n#include \"unterminated\n");
    ASSERT_EQ(includes.size(), 2u);
    EXPECT_EQ(includes[0].header, "common/a.glsl");
    EXPECT_FALSE(includes[0].system);
    EXPECT_EQ(includes[1].header, "b.glsl");
    EXPECT_TRUE(includes[1].system);
}

TEST(SourceTree, NamesAreRelativeToTheRoot) {
    SourceTree tree("/r/shaders");
    EXPECT_EQ(tree.name_of("/r/shaders/common/x.glsl"), "common/x.glsl");
    EXPECT_EQ(tree.name_of("/r/shaders/a/../b.frag"), "b.frag");
    EXPECT_EQ(tree.name_of("/elsewhere/y.glsl"), "/elsewhere/y.glsl");
    EXPECT_EQ(tree.path_of("common/x.glsl"), std::filesystem::path("/r/shaders/common/x.glsl"));
    EXPECT_EQ(tree.path_of("/elsewhere/y.glsl"), std::filesystem::path("/elsewhere/y.glsl"));
}

}  // namespace
}  // namespace ds::shader
