// Every built-in scene and the real glTF test models render non-blank and validation-clean;
// an exported built-in scene renders like the built-in one.
#include <gtest/gtest.h>

#include "tests/render/capture_helpers.h"

using namespace ds::test;

class SceneRenders : public ::testing::TestWithParam<std::string> {};

TEST_P(SceneRenders, NonBlankAndValidationClean) {
    std::string tag = GetParam();
    for (char& ch : tag) ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
    Capture c = capture("scene-" + tag, GetParam(), "320x180");
    ASSERT_EQ(c.image.width, 320);
    // A blank frame is one clear colour. overdraw's nearest quad fills the whole view, so it
    // shows only a few shades; every other scene shows many.
    const size_t min_colours = GetParam() == "overdraw" ? 2 : 8;
    EXPECT_GT(distinct_colours(c.image), min_colours) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(BuiltIn, SceneRenders,
                         ::testing::Values("atrium", "overdraw", "zfight", "foliage", "edges",
                                           "decals"),
                         [](const auto& info) { return info.param; });

INSTANTIATE_TEST_SUITE_P(
    AssimpModels, SceneRenders,
    ::testing::Values(DS_ASSIMP_MODELS "/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb",
                      DS_ASSIMP_MODELS "/glTF2/BoxTextured-glTF/BoxTextured.gltf",
                      DS_ASSIMP_MODELS "/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb",
                      DS_ASSIMP_MODELS "/glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf"),
    [](const auto& info) { return "model" + std::to_string(info.index); });

class ExportRoundTrip : public ::testing::TestWithParam<std::string> {};

TEST_P(ExportRoundTrip, ExportedSceneRendersLikeTheBuiltIn) {
    const std::string name = GetParam();
    auto dir = fresh_dir("export-" + name);
    const auto gltf = dir / (name + ".gltf");
    auto r = run_depthscope("export-scene " + name + " " + gltf.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    ASSERT_TRUE(std::filesystem::exists(gltf));
    Capture built_in = capture("export-" + name + "-builtin", name, "320x180");
    Capture exported = capture("export-" + name + "-file", gltf.string(), "320x180");
    ASSERT_GT(built_in.image.width, 0);
    EXPECT_EQ(differing_pixels(built_in.image, exported.image, 0), 0u);
}

INSTANTIATE_TEST_SUITE_P(BuiltIn, ExportRoundTrip,
                         ::testing::Values("atrium", "overdraw", "zfight", "foliage", "edges",
                                           "decals"),
                         [](const auto& info) { return info.param; });
