// Missing, undecodable and unsupported textures (issue 27): a warning line each, the texture
// dropped from its materials and the capture written; with --strict one error line, exit 1,
// nothing written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/support/run_process.h"

namespace ds::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The foliage export (four PNG textures) with every image file it names removed.
fs::path foliage_without_textures(const std::string& name, std::vector<std::string>& removed) {
    const fs::path dir = fresh_dir(name);
    const fs::path gltf = dir / "foliage.gltf";
    EXPECT_EQ(run_depthscope("export-scene foliage " + gltf.string()).exit_code, 0);
    const json doc = json::parse(read_file(gltf));
    for (const json& image : doc["images"]) {
        removed.push_back(image["uri"].get<std::string>());
        fs::remove(dir / removed.back());
    }
    return gltf;
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> out;
    size_t start = 0;
    for (size_t end; (end = text.find('\n', start)) != std::string::npos; start = end + 1)
        out.push_back(text.substr(start, end - start));
    return out;
}

TEST(MissingTextures, AWarningEachAndTheCaptureIsWritten) {
    std::vector<std::string> removed;
    const fs::path gltf = foliage_without_textures("missing-textures", removed);
    ASSERT_EQ(removed.size(), 4u);
    const fs::path out = gltf.parent_path() / "cap";
    const ProcessResult r = run_depthscope("capture --validate --size 160x90 --scene " +
                                           gltf.string() + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::exists(out / "final.png"));
    std::set<std::string> named;
    for (const std::string& line : lines_of(r.err)) {
        if (line.find("no such file") == std::string::npos) continue;
        EXPECT_EQ(line.rfind("depthscope: warning: ", 0), 0u) << line;
        for (const std::string& file : removed)
            if (line.find(file) != std::string::npos) named.insert(file);
    }
    EXPECT_EQ(named.size(), 4u) << r.err;
    // A masked material says what its alpha test reads now.
    EXPECT_NE(r.err.find("baseColorFactor's alpha"), std::string::npos) << r.err;
    const json report = json::parse(read_file(out / "report.json"));
    EXPECT_GE(report["scene"]["warnings"].size(), 4u);
}

// Every command that loads the scene says so, a line per texture, and goes on: the lists, the
// diagnostics, the benchmark and the replay of a capture made without the textures.
TEST(MissingTextures, EveryCommandThatLoadsTheScenePrintsTheWarnings) {
    std::vector<std::string> removed;
    const fs::path gltf = foliage_without_textures("missing-textures-commands", removed);
    const fs::path dir = gltf.parent_path();
    const std::string scene = gltf.string();
    ASSERT_EQ(
        run_depthscope("capture --size 32x18 --scene " + scene + " --out " + (dir / "cap").string())
            .exit_code,
        0);
    for (const std::string& args :
         {"cameras " + scene, "diagnose --size 32x18 --scene " + scene,
          "bench --frames 1 --warmup 0 --size 32x18 --scene " + scene,
          "pixel --size 32x18 --at 1,1 --scene " + scene,
          "replay " + (dir / "cap").string() + " --out " + (dir / "again").string()}) {
        SCOPED_TRACE(args);
        const ProcessResult r = run_depthscope(args);
        EXPECT_EQ(r.exit_code, 0) << r.err;
        size_t warnings = 0;
        for (const std::string& line : lines_of(r.err))
            if (line.rfind("depthscope: warning: ", 0) == 0 &&
                line.find("no such file") != std::string::npos)
                ++warnings;
        EXPECT_EQ(warnings, removed.size()) << r.err;
    }
}

TEST(MissingTextures, StrictRefusesWithOneLineAndWritesNothing) {
    std::vector<std::string> removed;
    const fs::path gltf = foliage_without_textures("missing-textures-strict", removed);
    const fs::path out = gltf.parent_path() / "cap";
    const ProcessResult r = run_depthscope("capture --strict --size 160x90 --scene " +
                                           gltf.string() + " --out " + out.string());
    expect_one_error_line(r, 1, "no such file");
    EXPECT_FALSE(fs::exists(out));
    // Every other command that loads a scene (view needs a window: the same load_scene call).
    const std::string scene = gltf.string();
    for (const std::string& args :
         {"cameras --strict " + scene, "diagnose --strict --size 32x18 --scene " + scene,
          "bench --strict --frames 1 --warmup 0 --size 32x18 --scene " + scene,
          "pixel --strict --size 32x18 --at 1,1 --scene " + scene}) {
        SCOPED_TRACE(args);
        expect_one_error_line(run_depthscope(args), 1, "no such file");
    }
}

// An image that does not decode and a texture whose image only KHR_texture_basisu holds.
TEST(MissingTextures, UndecodableAndUnsupportedTexturesAreWarnings) {
    std::vector<std::string> removed;
    const fs::path gltf = foliage_without_textures("undecodable-textures", removed);
    const fs::path dir = gltf.parent_path();
    { std::ofstream(dir / removed[0]) << "not a png"; }
    json doc = json::parse(read_file(gltf));
    doc["textures"][1].erase("source");
    doc["textures"][1]["extensions"]["KHR_texture_basisu"] = {{"source", 1}};
    doc["extensionsUsed"].push_back("KHR_texture_basisu");
    doc["extensionsRequired"] = {"KHR_texture_basisu"};
    { std::ofstream(gltf) << doc.dump(); }
    const ProcessResult r = run_depthscope("capture --size 160x90 --scene " + gltf.string() +
                                           " --out " + (dir / "cap").string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("not a PNG or JPEG"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("KHR_texture_basisu, which is not supported"), std::string::npos) << r.err;
    const ProcessResult strict =
        run_depthscope("capture --strict --size 160x90 --scene " + gltf.string() + " --out " +
                       (dir / "strict").string());
    EXPECT_EQ(strict.exit_code, 1) << strict.err;
    EXPECT_FALSE(fs::exists(dir / "strict"));
}

}  // namespace
}  // namespace ds::test
