#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>

#include "renderer/shader/compiler.h"
#include "tests/unit/shader/shader_test_fixture.h"

namespace ds::shader::testing {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> entries_in(const fs::path& dir) {
    std::vector<fs::path> entries;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) entries.push_back(entry.path());
    return entries;
}

class CacheTest : public ShaderTest {
  protected:
    void SetUp() override {
        ShaderTest::SetUp();
        write("main.frag", kIncludingFragment);
        write("common/inc.glsl", include_returning("2.0"));
    }
    CompileResult compile(Compiler& compiler, const std::vector<Define>& defines = {}) {
        return compiler.compile("main.frag", Stage::Fragment, defines);
    }
};

TEST_F(CacheTest, SecondCompileIsAHitWithIdenticalSpirv) {
    Compiler compiler(root(), cache());
    const CompileResult first = compile(compiler);
    const CompileResult second = compile(compiler);
    EXPECT_FALSE(first.from_cache);
    EXPECT_TRUE(second.from_cache);
    EXPECT_EQ(first.spirv, second.spirv);
    EXPECT_EQ(first.files, second.files);
    EXPECT_EQ(compiler.stats().compiles, 1u);
    EXPECT_EQ(compiler.stats().cache_hits, 1u);
    // Persisted on disk, not just in memory: a fresh compiler hits too.
    Compiler fresh(root(), cache());
    EXPECT_TRUE(compile(fresh).from_cache);
    EXPECT_EQ(fresh.stats().compiles, 0u);
    // Atomic writes leave no temp files behind.
    EXPECT_EQ(entries_in(cache()).size(), 1u);
}

TEST_F(CacheTest, DefinesChangeTheKey) {
    write("main.frag", R"(#version 460
layout(location = 0) out vec4 color;
void main() {
#ifdef RED
    color = vec4(1.0, 0.0, 0.0, 1.0);
#else
    color = vec4(0.0, 1.0, 0.0, 1.0);
#endif
}
)");
    Compiler compiler(root(), cache());
    const auto plain = compile(compiler);
    const auto red = compile(compiler, {{"RED", "1"}});
    const auto red_value = compile(compiler, {{"RED", "2"}});  // same code, other key
    EXPECT_FALSE(red.from_cache);
    EXPECT_FALSE(red_value.from_cache);
    EXPECT_NE(plain.spirv, red.spirv);
    EXPECT_EQ(red.spirv, red_value.spirv);
    EXPECT_EQ(compiler.stats().compiles, 3u);
    EXPECT_TRUE(compile(compiler, {{"RED", "1"}}).from_cache);
    EXPECT_TRUE(compile(compiler).from_cache);
    EXPECT_EQ(compiler.stats().cache_hits, 2u);
}

TEST_F(CacheTest, StageIsPartOfTheKey) {
    write("shared.glsl", "#version 460\nvoid main() {}\n");
    Compiler compiler(root(), cache());
    compiler.compile("shared.glsl", Stage::Vertex);
    EXPECT_FALSE(compiler.compile("shared.glsl", Stage::Fragment).from_cache);
    EXPECT_EQ(compiler.stats().compiles, 2u);
}

TEST_F(CacheTest, EditingAnIncludeInvalidatesTheEntry) {
    Compiler compiler(root(), cache());
    const auto before = compile(compiler);
    write("common/inc.glsl", include_returning("3.0"));
    const auto after = compile(compiler);
    EXPECT_FALSE(after.from_cache);
    EXPECT_NE(before.spirv, after.spirv);
    EXPECT_EQ(compiler.stats().compiles, 2u);
    // Putting the old text back finds the old entry again.
    write("common/inc.glsl", include_returning("2.0"));
    const auto restored = compile(compiler);
    EXPECT_TRUE(restored.from_cache);
    EXPECT_EQ(restored.spirv, before.spirv);
}

TEST_F(CacheTest, EditingANestedIncludeInvalidatesTheEntry) {
    write("common/inc.glsl", "#include \"nested.glsl\"\n" + include_returning("K"));
    write("common/nested.glsl", "const float K = 2.0;\n");
    Compiler compiler(root(), cache());
    const auto before = compile(compiler);
    write("common/nested.glsl", "const float K = 4.0;\n");
    const auto after = compile(compiler);
    EXPECT_FALSE(after.from_cache);
    EXPECT_NE(before.spirv, after.spirv);
}

TEST_F(CacheTest, CorruptEntriesAreIgnoredAndReplaced) {
    Compiler compiler(root(), cache());
    const auto good = compile(compiler);
    const auto entries = entries_in(cache());
    ASSERT_EQ(entries.size(), 1u);
    const auto size = fs::file_size(entries[0]);

    for (const std::string& garbage :
         {std::string("not spirv at all"), std::string(), std::string(size, '\0')}) {
        std::ofstream(entries[0], std::ios::binary | std::ios::trunc) << garbage;
        const auto result = compile(compiler);
        EXPECT_FALSE(result.from_cache);
        EXPECT_EQ(result.spirv, good.spirv);
    }
    // Flip one byte of the SPIR-V body: the checksum catches it.
    {
        std::fstream file(entries[0], std::ios::binary | std::ios::in | std::ios::out);
        file.seekp(static_cast<std::streamoff>(size - 3));
        file.put('\x5a');
    }
    EXPECT_FALSE(compile(compiler).from_cache);
    // Each miss rewrote the entry, so it is good again.
    EXPECT_TRUE(compile(compiler).from_cache);
    EXPECT_EQ(compiler.stats().compiles, 5u);
}

TEST_F(CacheTest, UnwritableCacheStillCompiles) {
    // A regular file where the cache folder should be: no folder can be created under it
    // (unlike permission bits, this also holds when the tests run as root).
    std::ofstream(dir_ / "blocker") << "x";
    Compiler compiler(root(), dir_ / "blocker" / "spirv");
    EXPECT_FALSE(compile(compiler).spirv.empty());
    EXPECT_FALSE(compile(compiler).from_cache);
    EXPECT_EQ(compiler.stats().compiles, 2u);

    Compiler on_a_file(root(), dir_ / "blocker");
    EXPECT_FALSE(compile(on_a_file).spirv.empty());
}

TEST_F(CacheTest, EmptyCacheDirDisablesTheCache) {
    Compiler compiler(root(), fs::path{});
    compile(compiler);
    EXPECT_FALSE(compile(compiler).from_cache);
    EXPECT_EQ(compiler.stats().compiles, 2u);
}

TEST_F(CacheTest, FailedCompilesAreNotCached) {
    write("common/inc.glsl", "float scale(float x) { return broken; }\n");
    Compiler compiler(root(), cache());
    EXPECT_THROW(compile(compiler), ShaderError);
    EXPECT_THROW(compile(compiler), ShaderError);
    EXPECT_EQ(compiler.stats().compiles, 2u);
    EXPECT_TRUE(entries_in(cache()).empty());
}

// Sets an environment variable for one scope; restores the old value after.
class ScopedEnv {
  public:
    ScopedEnv(const char* name, const char* value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        value ? ::setenv(name, value, 1) : ::unsetenv(name);
    }
    ~ScopedEnv() { old_ ? ::setenv(name_, old_->c_str(), 1) : ::unsetenv(name_); }

  private:
    const char* name_;
    std::optional<std::string> old_;
};

TEST(CompilerDefaults, CacheDirFollowsTheEnvironment) {
    ScopedEnv home("HOME", "/home/someone");
    {
        ScopedEnv ds("DEPTHSCOPE_CACHE_DIR", "/tmp/ds-cache");
        ScopedEnv xdg("XDG_CACHE_HOME", "/xdg");
        EXPECT_EQ(Compiler::default_cache_dir(), fs::path("/tmp/ds-cache"));
    }
    ScopedEnv ds("DEPTHSCOPE_CACHE_DIR", nullptr);
    {
        ScopedEnv xdg("XDG_CACHE_HOME", "/xdg");
        EXPECT_EQ(Compiler::default_cache_dir(), fs::path("/xdg/depthscope/spirv"));
    }
    {
        ScopedEnv xdg("XDG_CACHE_HOME", "relative/is/ignored");
        EXPECT_EQ(Compiler::default_cache_dir(), fs::path("/home/someone/.cache/depthscope/spirv"));
    }
    ScopedEnv xdg("XDG_CACHE_HOME", nullptr);
    EXPECT_EQ(Compiler::default_cache_dir(), fs::path("/home/someone/.cache/depthscope/spirv"));
    ScopedEnv no_home("HOME", nullptr);
    EXPECT_TRUE(Compiler::default_cache_dir().empty());
}

TEST(CompilerDefaults, ShaderRootFollowsTheEnvironment) {
    {
        ScopedEnv dir("DEPTHSCOPE_SHADER_DIR", "/somewhere/shaders");
        EXPECT_EQ(Compiler::default_shader_root(), fs::path("/somewhere/shaders"));
    }
    ScopedEnv dir("DEPTHSCOPE_SHADER_DIR", nullptr);
    EXPECT_EQ(Compiler::default_shader_root(), fs::path(DS_SHADER_DIR));
}

}  // namespace
}  // namespace ds::shader::testing
