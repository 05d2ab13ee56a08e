// Bad input ends in one line `depthscope: error: FILE: WHAT`, exit 1, and no output written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/support/run_process.h"

namespace fs = std::filesystem;
using ds::test::count_lines;
using ds::test::run_depthscope;

namespace {

void expect_input_error(const std::string& args, const std::string& mention) {
    auto r = run_depthscope(args, /*timeout_s=*/10);
    EXPECT_EQ(r.exit_code, 1) << args << "\n" << r.err;
    EXPECT_EQ(count_lines(r.err), 1u) << args << "\n" << r.err;
    EXPECT_EQ(r.err.rfind("depthscope: error: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(mention), std::string::npos) << r.err;
}

}  // namespace

TEST(BadInput, MissingFile) {
    expect_input_error("capture --scene /nonexistent/model.gltf --size 32x32",
                       "/nonexistent/model.gltf");
}

TEST(BadInput, BrokenGltfFilesFailCleanlyAndWriteNothing) {
    const fs::path root = DS_ASSIMP_MODELS "/glTF2";
    const char* files[] = {
        "IndexOutOfRange/IndexOutOfRange.gltf",
        "IndexOutOfRange/AllIndicesOutOfRange.gltf",
        "MissingBin/BoxTextured.gltf",
        "SchemaFailures/sceneWrongType.gltf",
        "wrongTypes/badArray.gltf",
        "wrongTypes/badNumber.gltf",
        "wrongTypes/badString.gltf",
        "wrongTypes/badObject.gltf",
        "wrongTypes/badUint.gltf",
        "RecursiveNodes/RecursiveNodes.gltf",
        "TestNoRootNode/NoScene.gltf",
        "BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb",
    };
    auto dir = ds::test::fresh_dir("bad-input");
    for (const char* f : files) {
        const fs::path out = dir / "cap";
        expect_input_error(
            "capture --size 32x32 --scene " + (root / f).string() + " --out " + out.string(),
            (root / f).string());
        EXPECT_FALSE(fs::exists(out)) << f;
    }
}

TEST(BadInput, Gltf1FilesAreRejected) {
    for (const auto& entry : fs::recursive_directory_iterator(DS_ASSIMP_MODELS "/glTF")) {
        const auto ext = entry.path().extension();
        if (ext != ".gltf" && ext != ".glb") continue;
        expect_input_error("capture --size 32x32 --scene " + entry.path().string(),
                           entry.path().string());
    }
}

TEST(BadInput, UnwritableOutputFolder) {
    // /proc refuses new folders even to root, so this holds for every user.
    auto r = run_depthscope("capture --scene overdraw --size 32x32 --out /proc/depthscope/cap");
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_EQ(count_lines(r.err), 1u) << r.err;
    EXPECT_NE(r.err.find("cannot create folder"), std::string::npos) << r.err;
}

TEST(BadInput, OutputPathThatIsAFile) {
    auto dir = ds::test::fresh_dir("out-is-file");
    { std::ofstream(dir / "taken") << "x"; }
    auto r =
        run_depthscope("capture --scene overdraw --size 32x32 --out " + (dir / "taken").string());
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find("not a folder"), std::string::npos) << r.err;
}
