// export_model writes a .gltf that loads back as the same scene, and never leaves partial
// output behind.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "model_view.h"
#include "renderer/common/error.h"
#include "renderer/scene/builtin/builtin.h"

namespace ds::scene::builtin {
namespace {

namespace fs = std::filesystem;

class ExportTest : public ::testing::Test {
  protected:
    void SetUp() override {
        std::random_device rd;
        dir_ = fs::temp_directory_path() /
               ("ds_builtin_export_" + std::to_string(::getpid()) + "_" + std::to_string(rd()));
        fs::create_directories(dir_);
    }
    void TearDown() override {
        fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add);
        fs::remove_all(dir_);
    }
    std::vector<std::string> entries() const {
        std::vector<std::string> out;
        for (const auto& e : fs::directory_iterator(dir_)) out.push_back(e.path().filename());
        std::sort(out.begin(), out.end());
        return out;
    }
    fs::path dir_;
};

tinygltf::Model load(const fs::path& path) {
    tinygltf::TinyGLTF loader;
    tinygltf::Model m;
    std::string err, warn;
    EXPECT_TRUE(loader.LoadASCIIFromFile(&m, &err, &warn, path.string())) << err;
    EXPECT_TRUE(err.empty()) << err;
    return m;
}

void expect_same_geometry(const tinygltf::Model& a, const tinygltf::Model& b) {
    ASSERT_EQ(a.meshes.size(), b.meshes.size());
    for (size_t i = 0; i < a.meshes.size(); ++i) {
        ASSERT_EQ(a.meshes[i].primitives.size(), b.meshes[i].primitives.size());
        const tinygltf::Primitive& pa = a.meshes[i].primitives[0];
        const tinygltf::Primitive& pb = b.meshes[i].primitives[0];
        EXPECT_EQ(pa.material, pb.material);
        ASSERT_EQ(pa.attributes.size(), pb.attributes.size());
        for (const auto& [name, acc] : pa.attributes) {
            ASSERT_TRUE(pb.attributes.count(name)) << name;
            EXPECT_EQ(a.accessors[acc].count, b.accessors[pb.attributes.at(name)].count);
        }
        EXPECT_EQ(test::read_vec3(a, pa.attributes.at("POSITION")),
                  test::read_vec3(b, pb.attributes.at("POSITION")));
        EXPECT_EQ(test::read_indices(a, pa.indices), test::read_indices(b, pb.indices));
    }
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    for (size_t i = 0; i < a.nodes.size(); ++i) {
        EXPECT_EQ(a.nodes[i].mesh, b.nodes[i].mesh);
        EXPECT_EQ(a.nodes[i].camera, b.nodes[i].camera);
        EXPECT_EQ(a.nodes[i].translation, b.nodes[i].translation);
        EXPECT_EQ(a.nodes[i].rotation, b.nodes[i].rotation);
        EXPECT_EQ(a.nodes[i].scale, b.nodes[i].scale);
    }
}

void expect_same_materials_and_pixels(const tinygltf::Model& a, const tinygltf::Model& b) {
    ASSERT_EQ(a.materials.size(), b.materials.size());
    for (size_t i = 0; i < a.materials.size(); ++i) {
        const tinygltf::Material& ma = a.materials[i];
        const tinygltf::Material& mb = b.materials[i];
        EXPECT_EQ(ma.name, mb.name);
        EXPECT_EQ(ma.alphaMode, mb.alphaMode);
        EXPECT_EQ(ma.alphaCutoff, mb.alphaCutoff);
        EXPECT_EQ(ma.doubleSided, mb.doubleSided);
        EXPECT_EQ(ma.pbrMetallicRoughness.baseColorFactor, mb.pbrMetallicRoughness.baseColorFactor);
        EXPECT_EQ(ma.pbrMetallicRoughness.roughnessFactor, mb.pbrMetallicRoughness.roughnessFactor);
        EXPECT_EQ(ma.pbrMetallicRoughness.baseColorTexture.index,
                  mb.pbrMetallicRoughness.baseColorTexture.index);
        EXPECT_EQ(ma.normalTexture.index, mb.normalTexture.index);
    }
    ASSERT_EQ(a.textures.size(), b.textures.size());
    ASSERT_EQ(a.images.size(), b.images.size());
    for (size_t i = 0; i < a.images.size(); ++i) {
        EXPECT_EQ(a.images[i].width, b.images[i].width);
        EXPECT_EQ(a.images[i].height, b.images[i].height);
        EXPECT_EQ(b.images[i].component, 4);
        EXPECT_TRUE(a.images[i].image == b.images[i].image) << "pixels of image " << i;
    }
    ASSERT_EQ(a.cameras.size(), b.cameras.size());
}

TEST_F(ExportTest, RoundTripGivesTheSameScene) {
    for (const char* name : {"atrium", "overdraw"}) {
        SCOPED_TRACE(name);
        const tinygltf::Model model = build(name, Settings());
        const fs::path out = dir_ / (std::string(name) + ".gltf");
        export_model(model, out);
        EXPECT_TRUE(fs::is_regular_file(out));
        EXPECT_TRUE(fs::is_regular_file(dir_ / (std::string(name) + ".bin")));
        const tinygltf::Model back = load(out);
        expect_same_geometry(model, back);
        expect_same_materials_and_pixels(model, back);
    }
    for (const std::string& e : entries()) EXPECT_NE(e[0], '.') << "leftover " << e;
    // One .gltf + .bin per scene, one PNG per atrium image (overdraw has none).
    EXPECT_EQ(entries().size(), 4 + build("atrium", Settings()).images.size());
}

TEST_F(ExportTest, ExportingTwiceOverwrites) {
    const tinygltf::Model model = build("foliage", Settings());
    export_model(model, dir_ / "scene.gltf");
    const auto first = entries();
    export_model(model, dir_ / "scene.gltf");
    EXPECT_EQ(entries(), first);
}

TEST_F(ExportTest, MissingFolderThrowsAndLeavesNothing) {
    const fs::path out = dir_ / "missing" / "atrium.gltf";
    EXPECT_THROW(export_model(build("atrium", Settings()), out), Error);
    EXPECT_FALSE(fs::exists(dir_ / "missing"));
    EXPECT_TRUE(entries().empty());
}

TEST_F(ExportTest, UnwritableFolderThrowsAndLeavesNothing) {
    if (::geteuid() == 0) GTEST_SKIP() << "root ignores folder permissions";
    fs::permissions(dir_, fs::perms::owner_read | fs::perms::owner_exec);
    EXPECT_THROW(export_model(build("overdraw", Settings()), dir_ / "o.gltf"), Error);
    fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add);
    EXPECT_TRUE(entries().empty());
}

TEST_F(ExportTest, ParentThatIsAFileThrowsAndLeavesNothing) {
    std::ofstream(dir_ / "plain_file") << "x";
    EXPECT_THROW(export_model(build("overdraw", Settings()), dir_ / "plain_file" / "o.gltf"),
                 Error);
    EXPECT_EQ(entries(), std::vector<std::string>{"plain_file"});
}

TEST_F(ExportTest, FolderThatRefusesNewFilesThrows) {
    // /proc refuses new entries even to root, for whom permission bits mean nothing.
    EXPECT_THROW(export_model(build("overdraw", Settings()), "/proc/ds_builtin_export.gltf"),
                 Error);
    EXPECT_FALSE(fs::exists("/proc/ds_builtin_export.gltf"));
}

TEST_F(ExportTest, ImageWithoutPixelsThrowsAndLeavesNothing) {
    tinygltf::Model model = build("atrium", Settings());
    model.images.back().image.clear();
    try {
        export_model(model, dir_ / "atrium.gltf");
        FAIL() << "no exception";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("cannot write"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(entries().empty());
}

TEST_F(ExportTest, FailureHalfwayRemovesWhatWasAlreadyMoved) {
    // A folder squatting on the last image's name: the .bin and the other PNGs are already in
    // place when its rename fails, and must be taken back.
    const tinygltf::Model model = build("atrium", Settings());
    const std::string last = model.images.back().name + ".png";
    fs::create_directory(dir_ / last);
    EXPECT_THROW(export_model(model, dir_ / "atrium.gltf"), Error);
    EXPECT_EQ(entries(), std::vector<std::string>{last});
}

}  // namespace
}  // namespace ds::scene::builtin
