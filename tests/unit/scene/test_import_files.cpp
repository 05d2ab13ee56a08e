// load_gltf on real files from Debian's assimp-testmodels: facts counted from the files
// themselves (python3 json over the .gltf / the GLB JSON chunk).
#include <filesystem>

#include <gtest/gtest.h>

#include "renderer/scene/importer.h"

namespace ds::scene {
namespace {

const std::filesystem::path kModels = DS_ASSIMP_MODELS;

std::filesystem::path model_path(const char* relative) {
    return kModels / "glTF2" / relative;
}

#define REQUIRE_MODELS()                             \
    if (!std::filesystem::exists(kModels / "glTF2")) \
    GTEST_SKIP() << "assimp-testmodels "             \
                    "not installed"

class BoxTextured : public ::testing::TestWithParam<const char*> {};

// One mesh with one primitive, one textured material, 12 triangles, in all three containers.
TEST_P(BoxTextured, Facts) {
    REQUIRE_MODELS();
    const Scene s = load_gltf(model_path(GetParam()));
    EXPECT_EQ(s.name, "BoxTextured");
    EXPECT_EQ(s.source, model_path(GetParam()).string());
    EXPECT_EQ(s.gltf_mesh_count, 1u);
    EXPECT_EQ(s.meshes.size(), 1u);
    EXPECT_EQ(s.materials.size(), 1u);
    EXPECT_EQ(s.textures.size(), 1u);
    EXPECT_EQ(s.draw_groups.size(), 1u);
    EXPECT_EQ(s.instances.size(), 1u);
    EXPECT_EQ(s.triangle_count(), 12u);
    EXPECT_EQ(s.meshes[0].vertices.size(), 24u);  // file normals kept: no unwelding
    ASSERT_TRUE(s.materials[0].base_color.present());
    ASSERT_EQ(s.images.size(), 1u);
    EXPECT_EQ(s.images[0].width, 211u);  // CesiumLogoFlat.png
    EXPECT_EQ(s.images[0].height, 211u);
    EXPECT_EQ(s.images[0].rgba8.size(), 211u * 211u * 4u);
    EXPECT_TRUE(s.images[0].srgb);
    EXPECT_EQ(s.samplers.size(), 2u);  // the file's + the default
    EXPECT_EQ(s.draw_groups[0].alpha_mode, AlphaMode::Opaque);
    EXPECT_FALSE(s.file_camera.has_value());
    EXPECT_TRUE(s.warnings.empty());
}

INSTANTIATE_TEST_SUITE_P(Containers, BoxTextured,
                         ::testing::Values("BoxTextured-glTF/BoxTextured.gltf",
                                           "BoxTextured-glTF-Binary/BoxTextured.glb",
                                           "BoxTextured-glTF-Embedded/BoxTextured.gltf"));

// The same engine with KHR_draco_mesh_compression (assimp's test model, a Draco encoder that
// is not gltf-pipeline): the same meshes and instances, positions within Draco's quantization
// of the uncompressed GLB's. Draco's encoder drops degenerate triangles (110,336 are left).
TEST(ImportFiles, TwoCylinderEngineDraco) {
    REQUIRE_MODELS();
    const Scene plain = load_gltf(model_path("2CylinderEngine-glTF-Binary/2CylinderEngine.glb"));
    const Scene draco = load_gltf(model_path("draco/2CylinderEngine.gltf"));
    EXPECT_EQ(draco.meshes.size(), plain.meshes.size());
    EXPECT_EQ(draco.instances.size(), plain.instances.size());
    EXPECT_EQ(draco.triangle_count(), 110336u);
    const glm::vec3 size = plain.bounds.extent();
    EXPECT_LT(glm::length(draco.bounds.min - plain.bounds.min), 0.01f * glm::length(size));
    EXPECT_LT(glm::length(draco.bounds.max - plain.bounds.max), 0.01f * glm::length(size));
    for (const std::string& w : draco.warnings)
        EXPECT_EQ(w.find("KHR_draco_mesh_compression"), std::string::npos) << w;
}

// 29 glTF meshes with 34 primitives placed by 67 mesh nodes: 115 primitive instances in 34
// groups (one per primitive: each has its own material), 121,496 triangles.
TEST(ImportFiles, TwoCylinderEngine) {
    REQUIRE_MODELS();
    const Scene s = load_gltf(model_path("2CylinderEngine-glTF-Binary/2CylinderEngine.glb"));
    EXPECT_EQ(s.gltf_mesh_count, 29u);
    EXPECT_EQ(s.meshes.size(), 34u);
    EXPECT_EQ(s.materials.size(), 34u);
    EXPECT_EQ(s.draw_groups.size(), 34u);
    EXPECT_EQ(s.instances.size(), 115u);
    EXPECT_EQ(s.triangle_count(), 121496u);
    uint32_t next = 0;
    for (const DrawGroup& g : s.draw_groups) {
        EXPECT_EQ(g.first_instance, next);  // contiguous, in order
        next += g.instance_count;
    }
    EXPECT_EQ(next, 115u);
    // Its one camera (node 81) becomes the file camera.
    ASSERT_TRUE(s.file_camera.has_value());
    EXPECT_NEAR(s.file_camera->yfov, 0.3143464f, 1e-6f);
    EXPECT_NEAR(s.file_camera->position.x, 1005.9874f, 1e-3f);
    EXPECT_NEAR(s.file_camera->position.y, 766.3171f, 1e-3f);
    EXPECT_NEAR(s.file_camera->position.z, 953.3456f, 1e-3f);
    EXPECT_NEAR(s.file_camera->znear, 0.05f, 1e-6f);
    EXPECT_FLOAT_EQ(s.file_camera->zfar, 1e6f);
    EXPECT_TRUE(s.bounds.valid());
}

// A square of POSITION only, seen by one perspective and one orthographic camera.
TEST(ImportFiles, CamerasAndFlatNormals) {
    REQUIRE_MODELS();
    const Scene s = load_gltf(model_path("cameras/Cameras.gltf"));
    ASSERT_TRUE(s.file_camera.has_value());
    EXPECT_FLOAT_EQ(s.file_camera->yfov, 0.7f);
    EXPECT_FLOAT_EQ(s.file_camera->znear, 0.01f);
    EXPECT_FLOAT_EQ(s.file_camera->zfar, 100.0f);
    EXPECT_EQ(s.file_camera->position, glm::vec3(0.5f, 0.5f, 3.0f));
    EXPECT_EQ(s.file_camera->forward, glm::vec3(0, 0, -1));
    EXPECT_EQ(s.camera.position, s.file_camera->position);
    // No NORMAL: unwelded into 2 × 3 vertices with the face normal (+Z for this winding).
    ASSERT_EQ(s.meshes.size(), 1u);
    EXPECT_EQ(s.meshes[0].vertices.size(), 6u);
    for (const Vertex& v : s.meshes[0].vertices) EXPECT_EQ(v.normal, glm::vec3(0, 0, 1));
    // No material: the default one is appended.
    ASSERT_EQ(s.materials.size(), 1u);
    EXPECT_EQ(s.materials[0].name, "default");
}

// The same indexed square [1, 0, 3, 1, 3, 2] stored as unsigned int, byte and short.
TEST(ImportFiles, IndexComponentTypes) {
    REQUIRE_MODELS();
    const char* files[] = {"Mesh_PrimitiveMode_13.gltf", "Mesh_PrimitiveMode_14.gltf",
                           "Mesh_PrimitiveMode_15.gltf"};
    const std::filesystem::path dir = model_path("glTF-Asset-Generator/Mesh_PrimitiveMode");
    const glm::vec3 p[4] = {{0.5f, -0.5f, 0}, {-0.5f, -0.5f, 0}, {-0.5f, 0.5f, 0}, {0.5f, 0.5f, 0}};
    const int want[6] = {1, 0, 3, 1, 3, 2};
    for (const char* file : files) {
        const Scene s = load_gltf(dir / file);
        ASSERT_EQ(s.meshes.size(), 1u) << file;
        const Mesh& m = s.meshes[0];
        ASSERT_EQ(m.vertices.size(), 6u) << file;  // no normals in these files: unwelded
        for (int i = 0; i < 6; ++i) EXPECT_EQ(m.vertices[i].position, p[want[i]]) << file << i;
        EXPECT_EQ(s.triangle_count(), 2u);
    }
}

// Shading-only extensions are ignored, not refused.
TEST(ImportFiles, IgnorableExtensionsLoad) {
    REQUIRE_MODELS();
    const Scene c = load_gltf(model_path("ClearCoat-glTF/ClearCoatTest.gltf"));
    EXPECT_EQ(c.triangle_count(), 37116u);
    EXPECT_EQ(c.warnings, std::vector<std::string>{"extension KHR_materials_clearcoat is ignored"});
    const Scene t = load_gltf(model_path("textureTransform/TextureTransformTest.gltf"));
    EXPECT_EQ(t.instances.size(), 12u);
    EXPECT_EQ(t.textures.size(), 5u);
}

}  // namespace
}  // namespace ds::scene
