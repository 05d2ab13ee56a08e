// import_model validation: every broken model below must be a one-line InputError
// "SOURCE: WHAT", never a crash or an out-of-bounds read.
#include <cmath>
#include <cstring>
#include <limits>

#include <gtest/gtest.h>

#include "model_builder.h"
#include "renderer/common/error.h"
#include "renderer/scene/importer.h"

namespace ds::scene {
namespace {

using test::ModelBuilder;

TEST(ImportValidation, IndexOutOfRange) {
    ModelBuilder b;
    const int mesh = b.add_quad_mesh();
    b.add_node(mesh);
    b.model.meshes[mesh].primitives[0].indices =
        b.add_indices<uint16_t>({0, 1, 4}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
    EXPECT_IMPORT_ERROR(b.model, "index 4 out of range");
}

TEST(ImportValidation, AccessorOutOfBufferViewRange) {
    ModelBuilder b;
    const int mesh = b.add_quad_mesh();
    b.add_node(mesh);
    b.model.accessors[0].count = 5;  // 4 positions are stored
    EXPECT_IMPORT_ERROR(b.model, "accessor 0 out of bufferView range");
}

TEST(ImportValidation, BufferViewOutOfBufferRange) {
    ModelBuilder b;
    b.add_node(b.add_quad_mesh());
    b.model.bufferViews[1].byteLength += 1000;
    EXPECT_IMPORT_ERROR(b.model, "bufferView 1 out of buffer range");
}

TEST(ImportValidation, MissingBufferData) {
    ModelBuilder b;
    b.add_node(b.add_quad_mesh());
    b.model.buffers[0].data.clear();
    EXPECT_IMPORT_ERROR(b.model, "out of buffer range");
}

TEST(ImportValidation, WrongComponentTypes) {
    {
        ModelBuilder b;
        const int mesh = b.add_quad_mesh();
        b.add_node(mesh);
        b.model.accessors[0].componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
        b.model.accessors[0].count = 2;  // keep it inside its buffer view
        EXPECT_IMPORT_ERROR(b.model, "POSITION (accessor 0): component type unsigned short");
    }
    {
        ModelBuilder b;
        const int mesh = b.add_quad_mesh();
        b.add_node(mesh);
        const int idx = b.model.meshes[mesh].primitives[0].indices;
        b.model.accessors[idx].componentType = TINYGLTF_COMPONENT_TYPE_SHORT;
        EXPECT_IMPORT_ERROR(b.model, "indices (accessor 1): component type short");
    }
    {
        ModelBuilder b;
        const int mesh = b.add_quad_mesh();
        b.add_node(mesh);
        b.model.accessors[0].type = TINYGLTF_TYPE_VEC2;
        EXPECT_IMPORT_ERROR(b.model, "POSITION (accessor 0): type must be VEC3");
    }
}

TEST(ImportValidation, NonFiniteValues) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    for (const char* attribute : {"POSITION", "NORMAL"}) {
        ModelBuilder b;
        const int mesh = b.add_quad_mesh();
        b.add_node(mesh);
        const int acc = b.model.meshes[mesh].primitives[0].attributes[attribute];
        const auto& view = b.model.bufferViews[b.model.accessors[acc].bufferView];
        std::memcpy(&b.model.buffers[0].data[view.byteOffset + 4], &nan, 4);
        EXPECT_IMPORT_ERROR(b.model, std::string(attribute) + " (accessor");
    }
    {
        ModelBuilder b;
        const int mesh = b.add_quad_mesh();
        b.add_node(mesh);
        const int acc = b.model.meshes[mesh].primitives[0].attributes["TEXCOORD_0"];
        const auto& view = b.model.bufferViews[b.model.accessors[acc].bufferView];
        std::memcpy(&b.model.buffers[0].data[view.byteOffset], &inf, 4);
        EXPECT_IMPORT_ERROR(b.model, "TEXCOORD_0 (accessor 3): non-finite value");
    }
    {
        ModelBuilder b;
        const int node = b.add_node(b.add_quad_mesh());
        b.model.nodes[node].translation = {0, std::nan(""), 0};
        EXPECT_IMPORT_ERROR(b.model, "node 0 translation is not finite");
    }
    {
        ModelBuilder b;
        const int node = b.add_node(b.add_quad_mesh());
        b.model.nodes[node].matrix.assign(16, 1e300);  // beyond float range
        EXPECT_IMPORT_ERROR(b.model, "node 0 matrix is not finite");
    }
}

TEST(ImportValidation, RecursiveNodes) {
    ModelBuilder b;
    const int n0 = b.add_node(b.add_quad_mesh());
    const int n1 = b.add_node(-1, {}, /*root=*/false);
    b.model.nodes[n0].children = {n1};
    b.model.nodes[n1].children = {n0};
    EXPECT_IMPORT_ERROR(b.model, "node 0 is its own ancestor");
    b.model.nodes[n1].children = {n1};
    EXPECT_IMPORT_ERROR(b.model, "node 1 is its own ancestor");
}

TEST(ImportValidation, NodeWithTwoParents) {
    ModelBuilder b;
    const int shared = b.add_node(b.add_quad_mesh(), {}, /*root=*/false);
    b.model.nodes[b.add_node(-1)].children = {shared};
    b.model.nodes[b.add_node(-1)].children = {shared};
    EXPECT_IMPORT_ERROR(b.model, "node 0 is reached twice");
}

TEST(ImportValidation, IndicesOutOfRange) {
    auto check = [](auto mutate, const std::string& what) {
        ModelBuilder b;
        const int image = b.add_image(1, 1, 4, 8, {0, 0, 0, 0});
        b.add_texture(image);
        const int m = b.add_material();
        b.model.materials[m].pbrMetallicRoughness.baseColorTexture.index = 0;
        b.add_node(b.add_quad_mesh(m));
        mutate(b.model);
        EXPECT_IMPORT_ERROR(b.model, what);
    };
    check([](tinygltf::Model& m) { m.scenes[0].nodes = {7}; }, "scene 0: node 7 out of range");
    check([](tinygltf::Model& m) { m.nodes[0].children = {9}; }, "child node 9 out of range");
    check([](tinygltf::Model& m) { m.nodes[0].mesh = 4; }, "node 0: mesh 4 out of range");
    check([](tinygltf::Model& m) { m.nodes[0].camera = 2; }, "node 0: camera 2 out of range");
    check([](tinygltf::Model& m) { m.meshes[0].primitives[0].material = 5; },
          "material 5 out of range");
    check([](tinygltf::Model& m) { m.materials[0].normalTexture.index = 3; },
          "normalTexture: texture 3 out of range");
    check([](tinygltf::Model& m) { m.textures[0].source = 2; }, "texture 0: image 2 out of range");
    check([](tinygltf::Model& m) { m.textures[0].sampler = 1; },
          "texture 0: sampler 1 out of range");
    check([](tinygltf::Model& m) { m.meshes[0].primitives[0].attributes["NORMAL"] = 99; },
          "NORMAL: accessor 99 out of range");
    check([](tinygltf::Model& m) { m.meshes[0].primitives[0].indices = 42; },
          "accessor 42 out of range");
    check([](tinygltf::Model& m) { m.accessors[0].bufferView = 42; },
          "accessor 0: bufferView 42 out of range");
    check([](tinygltf::Model& m) { m.bufferViews[0].buffer = 3; },
          "bufferView 0: buffer 3 out of range");
}

TEST(ImportValidation, BadImages) {
    auto check = [](auto mutate, const std::string& what) {
        ModelBuilder b;
        b.add_image(2, 2, 4, 8, std::vector<unsigned char>(16, 0));
        b.add_node(b.add_quad_mesh());
        mutate(b.model.images[0]);
        EXPECT_IMPORT_ERROR(b.model, what);
    };
    check([](tinygltf::Image& i) { i.image.clear(); }, "image 0: no pixel data");
    check([](tinygltf::Image& i) { i.image.resize(15); }, "pixel data is 15 bytes, need 16");
    check([](tinygltf::Image& i) { i.width = 0; }, "invalid size 0x2");
    check([](tinygltf::Image& i) { i.component = 5; }, "invalid component count 5");
    check([](tinygltf::Image& i) { i.bits = 32; }, "unsupported bit depth 32");
}

TEST(ImportValidation, MissingPositionAndBadCounts) {
    {
        ModelBuilder b;
        const int mesh = b.add_quad_mesh();
        b.add_node(mesh);
        b.model.meshes[mesh].primitives[0].attributes.erase("POSITION");
        EXPECT_IMPORT_ERROR(b.model, "mesh 0 primitive 0: no POSITION attribute");
    }
    {
        ModelBuilder b;
        const int mesh = b.add_quad_mesh();
        b.add_node(mesh);
        b.model.accessors[b.model.meshes[mesh].primitives[0].attributes["NORMAL"]].count = 3;
        EXPECT_IMPORT_ERROR(b.model, "NORMAL has 3 elements but POSITION has 4");
    }
    {
        ModelBuilder b;
        const int mesh = b.add_quad_mesh();
        b.add_node(mesh);
        b.model.accessors[b.model.meshes[mesh].primitives[0].indices].count = 5;
        EXPECT_IMPORT_ERROR(b.model, "5 indices is not a multiple of 3");
    }
    {
        ModelBuilder b;
        b.add_node(b.add_mesh({}));
        EXPECT_IMPORT_ERROR(b.model, "mesh 0 has no primitives");
    }
}

TEST(ImportValidation, VersionAndRequiredExtensions) {
    ModelBuilder b;
    b.add_node(b.add_quad_mesh());
    b.model.extensionsRequired = {"KHR_materials_clearcoat", "KHR_texture_transform"};
    EXPECT_NO_THROW(import_model(b.model, "t", "mem:t"));  // shading-only: ignored
    b.model.extensionsRequired = {"KHR_mesh_quantization", "EXT_meshopt_compression",
                                  "KHR_draco_mesh_compression", "KHR_texture_basisu"};
    EXPECT_NO_THROW(import_model(b.model, "t", "mem:t"));  // decoded, or textures dropped
    b.model.extensionsRequired = {"EXT_no_such_extension"};
    EXPECT_IMPORT_ERROR(b.model, "required extension EXT_no_such_extension is not supported");
    b.model.extensionsRequired = {"KHR_meshopt_compression"};
    EXPECT_IMPORT_ERROR(b.model, "decodes EXT_meshopt_compression only");
    b.model.extensionsRequired.clear();
    b.model.asset.version = "1.0";
    EXPECT_IMPORT_ERROR(b.model, "glTF 1.0 is not supported (need 2.0)");
}

TEST(ImportValidation, BadMaterialValues) {
    ModelBuilder b;
    const int m = b.add_material("CUTOUT");
    b.add_node(b.add_quad_mesh(m));
    EXPECT_IMPORT_ERROR(b.model, "material 0: unknown alphaMode \"CUTOUT\"");
    b.model.materials[0].alphaMode = "MASK";
    b.model.materials[0].pbrMetallicRoughness.baseColorFactor = {1, 1, 1};
    EXPECT_IMPORT_ERROR(b.model, "baseColorFactor must have 4 numbers");
    b.model.materials[0].pbrMetallicRoughness.baseColorFactor = {1, 1, 1, 1};
    b.model.materials[0].alphaCutoff = std::numeric_limits<double>::infinity();
    EXPECT_IMPORT_ERROR(b.model, "alphaCutoff is not finite");
}

}  // namespace
}  // namespace ds::scene
