// load_scene: built-in names and file paths.
#include <filesystem>

#include <gtest/gtest.h>

#include "renderer/common/error.h"
#include "renderer/scene/builtin/builtin.h"
#include "renderer/scene/loader.h"

namespace ds::scene {
namespace {

std::string load_error(std::string_view name) {
    try {
        load_scene(name, Settings{});
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(Loader, MissingFile) {
    EXPECT_EQ(load_error("no/such/model.glb"), "no/such/model.glb: no such file");
}

TEST(Loader, UnknownBareNameListsTheBuiltIns) {
    const std::string message = load_error("atrum");
    EXPECT_EQ(message.rfind("atrum: no such file (built-in scenes: ", 0), 0u) << message;
    EXPECT_NE(message.find(builtin::list().front().name), std::string::npos) << message;
}

TEST(Loader, FilePath) {
    const std::filesystem::path file =
        std::filesystem::path(DS_ASSIMP_MODELS) / "glTF2/BoxTextured-glTF/BoxTextured.gltf";
    if (!std::filesystem::exists(file)) GTEST_SKIP() << "assimp-testmodels not installed";
    const Scene s = load_scene(file.string(), Settings{});
    EXPECT_EQ(s.source, file.string());
    EXPECT_EQ(s.triangle_count(), 12u);
}

// Every built-in scene goes through the importer cleanly: no warnings, something to draw.
TEST(Loader, EveryBuiltInImports) {
    for (const builtin::Info& info : builtin::list()) {
        const Scene s = load_scene(info.name, Settings{});
        EXPECT_EQ(s.name, info.name);
        EXPECT_EQ(s.source, "builtin:" + info.name);
        EXPECT_FALSE(s.draw_groups.empty()) << info.name;
        EXPECT_GT(s.triangle_count(), 0u) << info.name;
        EXPECT_TRUE(s.warnings.empty()) << info.name << ": " << s.warnings.front();
    }
}

}  // namespace
}  // namespace ds::scene
