// Deliberately broken files of assimp-testmodels and every glTF 1.0 file: each must fail with a
// one-line InputError "PATH: WHAT". The table says why each file is broken; a new file in
// one of these folders fails the Coverage test until it is added here.
#include <filesystem>
#include <set>

#include <gtest/gtest.h>

#include "renderer/common/error.h"
#include "renderer/scene/importer.h"

namespace ds::scene {
namespace {

namespace fs = std::filesystem;
const fs::path kBrokenModels = DS_ASSIMP_MODELS;

struct Broken {
    const char* file;  // relative to the models root
    const char* what;  // expected part of the message
};

// Why each file is broken (all of them are: none is a valid glTF 2.0 scene we could draw).
constexpr Broken kBroken[] = {
    // Index 255 in a 24-vertex mesh.
    {"glTF2/IndexOutOfRange/IndexOutOfRange.gltf", "index 255 out of range (24 vertices)"},
    // Every index is 65535.
    {"glTF2/IndexOutOfRange/AllIndicesOutOfRange.gltf", "index 65535 out of range"},
    // BoxTextured0.bin is not there (checked before tinygltf reads anything).
    {"glTF2/MissingBin/BoxTextured.gltf", "buffers[0].uri \"BoxTextured0.bin\": no such file"},
    // "scene": "hello" (tinygltf would silently fall back to no scene).
    {"glTF2/SchemaFailures/sceneWrongType.gltf", "scene must be a non-negative integer"},
    // wrongTypes: each breaks the glTF schema in one property; tinygltf ignores all but one.
    {"glTF2/wrongTypes/badArray.gltf", "meshes[0].primitives must be an array of objects"},
    {"glTF2/wrongTypes/badExtension.gltf",
     "baseColorTexture.extensions.KHR_texture_transform must be an object"},
    {"glTF2/wrongTypes/badNumber.gltf", "materials[0].normalTexture.scale must be a number"},
    {"glTF2/wrongTypes/badObject.gltf", "materials[0].pbrMetallicRoughness must be an object"},
    {"glTF2/wrongTypes/badString.gltf", "scenes[0].name must be a string"},
    {"glTF2/wrongTypes/badUint.gltf", "baseColorTexture.index must be a non-negative integer"},
    // -Inf/+Inf x coordinates in POSITION.
    {"glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb",
     "POSITION (accessor 2): non-finite value"},
    // Node 0 -> node 1 -> node 0.
    {"glTF2/RecursiveNodes/RecursiveNodes.gltf", "node 0 is its own ancestor"},
    // "scene": 0 but no scenes at all.
    {"glTF2/TestNoRootNode/NoScene.gltf", "no scene"},
    // A valid but empty scene: nothing for the renderer to draw (we refuse empty scenes).
    {"glTF2/TestNoRootNode/SceneWithoutNodes.gltf", "nothing to draw"},
    // Buffer views 2-4 reach past the 514-byte buffer (and meshes 1/5 have 35 vertices or
    // indices: not whole triangles).
    {"glTF2/IncorrectVertexArrays/Cube.gltf", "bufferView 2 out of buffer range"},
};

std::string file_load_error(const fs::path& path) {
    try {
        load_gltf(path);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

void expect_broken(const fs::path& path, const std::string& what) {
    const std::string message = file_load_error(path);
    ASSERT_FALSE(message.empty()) << path << " loaded";
    EXPECT_EQ(message.rfind(path.string() + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(what), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

class BrokenFile : public ::testing::TestWithParam<Broken> {};

TEST_P(BrokenFile, FailsWithOneLineInputError) {
    if (!fs::exists(kBrokenModels / "glTF2")) GTEST_SKIP() << "assimp-testmodels not installed";
    expect_broken(kBrokenModels / GetParam().file, GetParam().what);
}

INSTANTIATE_TEST_SUITE_P(Assimp, BrokenFile, ::testing::ValuesIn(kBroken));

std::vector<fs::path> gltf_files_under(const fs::path& dir) {
    std::vector<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(dir)) {
        const auto ext = entry.path().extension();
        if (entry.is_regular_file() && (ext == ".gltf" || ext == ".glb"))
            files.push_back(entry.path());
    }
    return files;
}

// Every .gltf/.glb under glTF/ is glTF 1.0: asset.version "1.0" or the number 1, or a GLB
// container of version 1.
TEST(BrokenFiles, GltfOneIsRefused) {
    if (!fs::exists(kBrokenModels / "glTF")) GTEST_SKIP() << "assimp-testmodels not installed";
    const auto files = gltf_files_under(kBrokenModels / "glTF");
    EXPECT_GE(files.size(), 7u);
    for (const fs::path& file : files) expect_broken(file, "glTF 1.0 is not supported (need 2.0)");
}

// Every glTF file in the broken folders is in the table above.
TEST(BrokenFiles, Coverage) {
    if (!fs::exists(kBrokenModels / "glTF2")) GTEST_SKIP() << "assimp-testmodels not installed";
    std::set<fs::path> listed;
    for (const Broken& b : kBroken) listed.insert(kBrokenModels / b.file);
    for (const char* dir : {"IndexOutOfRange", "MissingBin", "SchemaFailures", "wrongTypes",
                            "BoxWithInfinites-glTF-Binary", "RecursiveNodes", "TestNoRootNode",
                            "IncorrectVertexArrays"})
        for (const fs::path& file : gltf_files_under(kBrokenModels / "glTF2" / dir))
            EXPECT_TRUE(listed.count(file)) << file << " is not in the table";
}

TEST(BrokenFiles, MissingFileAndNotGltf) {
    expect_broken("/nonexistent/dir/model.gltf", "no such file");
    const fs::path dir = fs::temp_directory_path();
    expect_broken(dir, "is a directory");
    const fs::path junk = dir / "ds_scene_test_junk.gltf";
    {
        std::FILE* f = std::fopen(junk.c_str(), "wb");
        ASSERT_NE(f, nullptr);
        std::fputs("{\"asset\": {\"version\": \"2.0\"}, \"scenes\": [ {", f);  // truncated
        std::fclose(f);
    }
    expect_broken(junk, "invalid JSON");
    {
        std::FILE* f = std::fopen(junk.c_str(), "wb");
        std::fputs("glTF\x02", f);  // a GLB header cut short
        std::fclose(f);
    }
    expect_broken(junk, "truncated GLB");
    fs::remove(junk);
}

}  // namespace
}  // namespace ds::scene
