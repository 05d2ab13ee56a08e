// import_model on models built in memory (the built-in scene path): what the importer makes
// of each part of a valid model.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "model_builder.h"
#include "renderer/common/error.h"
#include "renderer/scene/importer.h"

namespace ds::scene {
namespace {

using test::ModelBuilder;

TEST(ImportMemory, QuadFacts) {
    ModelBuilder b;
    b.add_node(b.add_quad_mesh(b.add_material()));
    const Scene s = import_model(b.model, "quad", "builtin:quad");
    EXPECT_EQ(s.name, "quad");
    EXPECT_EQ(s.source, "builtin:quad");
    EXPECT_EQ(s.gltf_mesh_count, 1u);
    ASSERT_EQ(s.meshes.size(), 1u);
    EXPECT_EQ(s.meshes[0].vertices.size(), 4u);
    EXPECT_EQ(s.meshes[0].indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
    EXPECT_EQ(s.materials.size(), 1u);  // no default material needed
    EXPECT_EQ(s.samplers.size(), 1u);   // just the default sampler
    EXPECT_EQ(s.triangle_count(), 2u);
    EXPECT_EQ(s.bounds.min, glm::vec3(0, 0, 0));
    EXPECT_EQ(s.bounds.max, glm::vec3(1, 1, 0));
    EXPECT_FALSE(s.file_camera.has_value());
    EXPECT_TRUE(s.warnings.empty());
    // Generated tangents: +X for this mapping, unmirrored.
    EXPECT_EQ(s.meshes[0].vertices[0].tangent, glm::vec4(1, 0, 0, 1));
}

// The same triangles through unsigned byte, short and int indices.
TEST(ImportMemory, IndexComponentTypes) {
    for (int type : {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                     TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT}) {
        ModelBuilder b;
        tinygltf::Primitive p;
        p.attributes["POSITION"] = b.add_vec3({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
        p.attributes["NORMAL"] = b.add_vec3({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
        const std::vector<uint32_t> want = {3, 0, 2, 2, 0, 1};
        if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE)
            p.indices = b.add_indices(std::vector<uint8_t>(want.begin(), want.end()), type);
        else if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT)
            p.indices = b.add_indices(std::vector<uint16_t>(want.begin(), want.end()), type);
        else
            p.indices = b.add_indices(want, type);
        b.add_node(b.add_mesh({p}));
        const Scene s = import_model(b.model, "t", "mem:t");
        EXPECT_EQ(s.meshes.at(0).indices, want) << "component type " << type;
    }
}

TEST(ImportMemory, NoIndicesMeansSequential) {
    ModelBuilder b;
    tinygltf::Primitive p;
    p.attributes["POSITION"] = b.add_vec3({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}});
    p.attributes["NORMAL"] = b.add_vec3({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    b.add_node(b.add_mesh({p}));
    EXPECT_EQ(import_model(b.model, "t", "mem:t").meshes[0].indices,
              (std::vector<uint32_t>{0, 1, 2}));
}

TEST(ImportMemory, MissingNormalsAreFlatAndUnwelded) {
    ModelBuilder b;
    b.add_node(b.add_quad_mesh(-1, /*with_normals=*/false));
    const Scene s = import_model(b.model, "t", "mem:t");
    const Mesh& m = s.meshes.at(0);
    EXPECT_EQ(m.vertices.size(), 6u);
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
    for (const Vertex& v : m.vertices) EXPECT_EQ(v.normal, glm::vec3(0, 0, 1));
}

TEST(ImportMemory, DefaultMaterialIsAppendedOnlyWhenNeeded) {
    ModelBuilder b;
    b.add_material("MASK");
    b.add_node(b.add_quad_mesh(-1));
    const Scene s = import_model(b.model, "t", "mem:t");
    ASSERT_EQ(s.materials.size(), 2u);
    EXPECT_EQ(s.meshes[0].material, 1u);
    EXPECT_EQ(s.materials[1].alpha_mode, AlphaMode::Opaque);
    EXPECT_EQ(s.materials[1].base_color_factor, glm::vec4(1.0f));
}

// Groups follow first use; each group's instances are contiguous, in traversal order.
TEST(ImportMemory, DrawGroupsInAuthoredOrder) {
    ModelBuilder b;
    const int opaque = b.add_material("OPAQUE");
    const int masked = b.add_material("MASK", /*double_sided=*/true);
    const int a = b.add_quad_mesh(masked);
    const int c = b.add_quad_mesh(opaque);
    b.add_node(a, {1, 0, 0});
    b.add_node(c, {2, 0, 0});
    b.add_node(a, {3, 0, 0});
    b.add_node(c, {4, 0, 0});
    b.add_node(a, {5, 0, 0});
    const Scene s = import_model(b.model, "t", "mem:t");
    ASSERT_EQ(s.draw_groups.size(), 2u);
    const DrawGroup& g0 = s.draw_groups[0];
    const DrawGroup& g1 = s.draw_groups[1];
    EXPECT_EQ(g0.mesh, 0u);  // used first, though masked: never re-sorted by alpha mode
    EXPECT_EQ(g0.alpha_mode, AlphaMode::Mask);
    EXPECT_TRUE(g0.double_sided);
    EXPECT_EQ(g0.first_instance, 0u);
    EXPECT_EQ(g0.instance_count, 3u);
    EXPECT_EQ(g1.mesh, 1u);
    EXPECT_FALSE(g1.double_sided);
    EXPECT_EQ(g1.first_instance, 3u);
    EXPECT_EQ(g1.instance_count, 2u);
    const float xs[] = {1, 3, 5, 2, 4};
    ASSERT_EQ(s.instances.size(), 5u);
    for (size_t i = 0; i < 5; ++i) EXPECT_EQ(s.instances[i].world[3].x, xs[i]) << i;
    EXPECT_EQ(s.triangle_count(), 10u);
    EXPECT_EQ(s.bounds.max.x, 6.0f);
}

TEST(ImportMemory, HierarchyTransformsCompose) {
    ModelBuilder b;
    const int mesh = b.add_quad_mesh();
    const int parent = b.add_node(-1, {10, 0, 0});
    const int child = b.add_node(mesh, {0, 5, 0}, /*root=*/false);
    b.model.nodes[parent].children = {child};
    b.model.nodes[parent].scale = {2, 2, 2};
    const Scene s = import_model(b.model, "t", "mem:t");
    ASSERT_EQ(s.instances.size(), 1u);
    EXPECT_EQ(glm::vec3(s.instances[0].world[3]), glm::vec3(10, 10, 0));
    EXPECT_EQ(s.bounds.min, glm::vec3(10, 10, 0));
    EXPECT_EQ(s.bounds.max, glm::vec3(12, 12, 0));
}

TEST(ImportMemory, NonTriangleModesAreSkippedWithAWarning) {
    ModelBuilder b;
    tinygltf::Primitive lines;
    lines.attributes["POSITION"] = b.add_vec3({{0, 0, 0}, {1, 0, 0}});
    lines.mode = TINYGLTF_MODE_LINE;
    const int quad = b.add_quad_mesh();
    b.model.meshes[quad].primitives.push_back(lines);
    b.add_node(quad);
    const Scene s = import_model(b.model, "t", "mem:t");
    EXPECT_EQ(s.meshes.size(), 1u);
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_NE(s.warnings[0].find("skipped 1 LINES"), std::string::npos) << s.warnings[0];
}

TEST(ImportMemory, OnlyNonTrianglesIsNothingToDraw) {
    ModelBuilder b;
    tinygltf::Primitive points;
    points.attributes["POSITION"] = b.add_vec3({{0, 0, 0}});
    points.mode = TINYGLTF_MODE_POINTS;
    b.add_node(b.add_mesh({points}));
    EXPECT_IMPORT_ERROR(b.model, "nothing to draw");
}

TEST(ImportMemory, ImagesBecomeRGBA8) {
    ModelBuilder b;
    const int grey = b.add_image(1, 1, 1, 8, {100});
    const int grey_alpha = b.add_image(1, 1, 2, 8, {100, 50});
    const int rgb = b.add_image(1, 1, 3, 8, {1, 2, 3});
    std::vector<unsigned char> sixteen(8);
    const uint16_t px[4] = {65535, 0, 32896, 257};  // rounded to the nearest 8-bit value
    std::memcpy(sixteen.data(), px, 8);
    const int deep = b.add_image(1, 1, 4, 16, sixteen);
    for (int i : {grey, grey_alpha, rgb, deep}) b.add_texture(i);
    b.add_node(b.add_quad_mesh());
    const Scene s = import_model(b.model, "t", "mem:t");
    ASSERT_EQ(s.images.size(), 4u);
    EXPECT_EQ(s.images[0].rgba8, (std::vector<uint8_t>{100, 100, 100, 255}));
    EXPECT_EQ(s.images[1].rgba8, (std::vector<uint8_t>{100, 100, 100, 50}));
    EXPECT_EQ(s.images[2].rgba8, (std::vector<uint8_t>{1, 2, 3, 255}));
    EXPECT_EQ(s.images[3].rgba8, (std::vector<uint8_t>{255, 0, 128, 1}));
}

TEST(ImportMemory, SrgbOnlyForColourImages) {
    ModelBuilder b;
    std::vector<int> tex;
    for (int i = 0; i < 3; ++i) tex.push_back(b.add_texture(b.add_image(1, 1, 4, 8, {0, 0, 0, 0})));
    const int m = b.add_material();
    b.model.materials[m].pbrMetallicRoughness.baseColorTexture.index = tex[0];
    b.model.materials[m].emissiveTexture.index = tex[1];
    b.model.materials[m].normalTexture.index = tex[2];
    b.add_node(b.add_quad_mesh(m));
    const Scene s = import_model(b.model, "t", "mem:t");
    EXPECT_TRUE(s.images[0].srgb);
    EXPECT_TRUE(s.images[1].srgb);
    EXPECT_FALSE(s.images[2].srgb);
    EXPECT_EQ(s.materials[0].normal.texture, tex[2]);
}

TEST(ImportMemory, SamplersAndTheDefaultSampler) {
    ModelBuilder b;
    tinygltf::Sampler nearest;
    nearest.magFilter = TINYGLTF_TEXTURE_FILTER_NEAREST;
    nearest.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST;
    nearest.wrapS = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
    nearest.wrapT = TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT;
    b.model.samplers.push_back(nearest);
    const int image = b.add_image(1, 1, 4, 8, {0, 0, 0, 0});
    b.add_texture(image, 0);
    b.add_texture(image);  // no sampler: the default one
    b.add_node(b.add_quad_mesh());
    const Scene s = import_model(b.model, "t", "mem:t");
    ASSERT_EQ(s.samplers.size(), 2u);
    EXPECT_EQ(s.samplers[0].mag, Filter::Nearest);
    EXPECT_EQ(s.samplers[0].min, Filter::Linear);
    EXPECT_TRUE(s.samplers[0].mipmaps);
    EXPECT_EQ(s.samplers[0].mip, Filter::Nearest);
    EXPECT_EQ(s.samplers[0].wrap_s, Wrap::ClampToEdge);
    EXPECT_EQ(s.samplers[0].wrap_t, Wrap::MirroredRepeat);
    EXPECT_EQ(s.textures[0].sampler, 0u);
    EXPECT_EQ(s.textures[1].sampler, 1u);
    EXPECT_EQ(s.samplers[1].mag, Filter::Linear);
    EXPECT_TRUE(s.samplers[1].mipmaps);
}

TEST(ImportMemory, MaterialFactors) {
    ModelBuilder b;
    const int m = b.add_material("BLEND", true);
    auto& src = b.model.materials[m];
    src.pbrMetallicRoughness.baseColorFactor = {0.5, 0.25, 1, 0.75};
    src.pbrMetallicRoughness.metallicFactor = 0.2;
    src.pbrMetallicRoughness.roughnessFactor = 0.7;
    src.emissiveFactor = {1, 2, 3};
    src.alphaCutoff = 0.3;
    b.add_node(b.add_quad_mesh(m));
    const Scene s = import_model(b.model, "t", "mem:t");
    const Material& got = s.materials[0];
    EXPECT_EQ(got.base_color_factor, glm::vec4(0.5f, 0.25f, 1.0f, 0.75f));
    EXPECT_FLOAT_EQ(got.metallic_factor, 0.2f);
    EXPECT_FLOAT_EQ(got.roughness_factor, 0.7f);
    EXPECT_EQ(got.emissive_factor, glm::vec3(1, 2, 3));
    EXPECT_EQ(got.alpha_mode, AlphaMode::Blend);
    EXPECT_FLOAT_EQ(got.alpha_cutoff, 0.3f);
    EXPECT_TRUE(got.double_sided);
}

TEST(ImportMemory, FirstPerspectiveCameraInTraversal) {
    ModelBuilder b;
    tinygltf::Camera ortho;
    ortho.type = "orthographic";
    ortho.orthographic.xmag = ortho.orthographic.ymag = 1;
    ortho.orthographic.zfar = 10;
    tinygltf::Camera persp;
    persp.type = "perspective";
    persp.perspective.yfov = 0.5;
    persp.perspective.znear = 0.1;  // zfar absent: infinite in glTF
    b.model.cameras = {ortho, persp};
    b.add_node(b.add_quad_mesh());
    b.model.nodes[b.add_node(-1, {0, 0, 7})].camera = 0;
    b.model.nodes[b.add_node(-1, {0, 0, 5})].camera = 1;
    const Scene s = import_model(b.model, "t", "mem:t");
    ASSERT_TRUE(s.file_camera.has_value());
    EXPECT_EQ(s.file_camera->position, glm::vec3(0, 0, 5));
    EXPECT_EQ(s.file_camera->forward, glm::vec3(0, 0, -1));
    EXPECT_EQ(s.file_camera->up, glm::vec3(0, 1, 0));
    EXPECT_FLOAT_EQ(s.file_camera->yfov, 0.5f);
    EXPECT_GT(s.file_camera->zfar, 5.0f);  // finite, past the scene
    EXPECT_EQ(s.camera.position, s.file_camera->position);
}

TEST(ImportMemory, SceneChoice) {
    ModelBuilder b;
    b.add_node(b.add_quad_mesh());
    b.model.defaultScene = -1;  // none set: scene 0
    EXPECT_NO_THROW(import_model(b.model, "t", "mem:t"));
    b.model.defaultScene = 3;
    EXPECT_IMPORT_ERROR(b.model, "scene 3 out of range");
    b.model.scenes.clear();
    b.model.defaultScene = -1;
    EXPECT_IMPORT_ERROR(b.model, "no scene");
}

TEST(ImportMemory, SparseAccessor) {
    ModelBuilder b;
    const int mesh = b.add_quad_mesh();
    b.add_node(mesh);
    // Move vertex 2 to (5, 5, 0) through a sparse substitution.
    const int positions = b.model.meshes[mesh].primitives[0].attributes["POSITION"];
    const uint16_t index = 2;
    const glm::vec3 value(5, 5, 0);
    const int idx_acc =
        b.add_accessor(&index, 2, 1, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR);
    const int val_acc =
        b.add_accessor(&value, 12, 1, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3);
    auto& sparse = b.model.accessors[positions].sparse;
    sparse.isSparse = true;
    sparse.count = 1;
    sparse.indices.bufferView = b.model.accessors[idx_acc].bufferView;
    sparse.indices.byteOffset = 0;
    sparse.indices.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    sparse.values.bufferView = b.model.accessors[val_acc].bufferView;
    sparse.values.byteOffset = 0;
    const Scene s = import_model(b.model, "t", "mem:t");
    EXPECT_EQ(s.meshes[0].vertices[2].position, value);
    EXPECT_EQ(s.bounds.max, glm::vec3(5, 5, 0));
}

}  // namespace
}  // namespace ds::scene
