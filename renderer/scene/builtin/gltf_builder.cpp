#include "renderer/scene/builtin/gltf_builder.h"

namespace ds::scene::builtin {

namespace {

std::vector<double> to_doubles(const float* v, int n) {
    return std::vector<double>(v, v + n);
}

const char* alpha_name(Alpha alpha) {
    switch (alpha) {
        case Alpha::Mask:
            return "MASK";
        case Alpha::Blend:
            return "BLEND";
        case Alpha::Opaque:
            break;
    }
    return "OPAQUE";
}

}  // namespace

glm::quat yaw(float radians) {
    return glm::angleAxis(radians, glm::vec3(0.0f, 1.0f, 0.0f));
}

ModelBuilder::ModelBuilder() {
    model_.asset.version = "2.0";
    model_.asset.generator = "depthscope built-in scene";
    model_.buffers.emplace_back();
}

int ModelBuilder::add_view(const void* bytes, size_t size, int target) {
    std::vector<unsigned char>& data = model_.buffers[0].data;
    while (data.size() % 4 != 0) data.push_back(0);  // every component type here is 4 bytes
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = data.size();
    view.byteLength = size;
    view.target = target;
    const auto* p = static_cast<const unsigned char*>(bytes);
    data.insert(data.end(), p, p + size);
    model_.bufferViews.push_back(view);
    return static_cast<int>(model_.bufferViews.size()) - 1;
}

int ModelBuilder::add_accessor(int view, int component_type, int type, size_t count) {
    tinygltf::Accessor acc;
    acc.bufferView = view;
    acc.byteOffset = 0;
    acc.componentType = component_type;
    acc.type = type;
    acc.count = count;
    model_.accessors.push_back(acc);
    return static_cast<int>(model_.accessors.size()) - 1;
}

Geometry ModelBuilder::add_geometry(std::string_view name, const MeshData& mesh) {
    constexpr int kArray = TINYGLTF_TARGET_ARRAY_BUFFER;
    constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;
    const size_t n = mesh.positions.size();
    const std::vector<glm::vec4> tangents = compute_tangents(mesh);
    Geometry g;
    g.position = add_accessor(add_view(mesh.positions.data(), n * sizeof(glm::vec3), kArray),
                              kFloat, TINYGLTF_TYPE_VEC3, n);
    g.normal = add_accessor(add_view(mesh.normals.data(), n * sizeof(glm::vec3), kArray), kFloat,
                            TINYGLTF_TYPE_VEC3, n);
    g.uv = add_accessor(add_view(mesh.uvs.data(), n * sizeof(glm::vec2), kArray), kFloat,
                        TINYGLTF_TYPE_VEC2, n);
    g.tangent = add_accessor(add_view(tangents.data(), n * sizeof(glm::vec4), kArray), kFloat,
                             TINYGLTF_TYPE_VEC4, n);
    g.indices = add_accessor(add_view(mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t),
                                      TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                             TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                             mesh.indices.size());
    // glTF requires min/max on POSITION; importers use them for bounds.
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& p : mesh.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    tinygltf::Accessor& pos = model_.accessors[static_cast<size_t>(g.position)];
    pos.minValues = to_doubles(&lo.x, 3);
    pos.maxValues = to_doubles(&hi.x, 3);
    pos.name = std::string(name) + "_position";
    return g;
}

int ModelBuilder::add_mesh(std::string_view name, const Geometry& geometry, int material) {
    tinygltf::Primitive prim;
    prim.attributes["POSITION"] = geometry.position;
    prim.attributes["NORMAL"] = geometry.normal;
    prim.attributes["TEXCOORD_0"] = geometry.uv;
    prim.attributes["TANGENT"] = geometry.tangent;
    prim.indices = geometry.indices;
    prim.material = material;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    tinygltf::Mesh mesh;
    mesh.name = std::string(name);
    mesh.primitives.push_back(prim);
    model_.meshes.push_back(mesh);
    return static_cast<int>(model_.meshes.size()) - 1;
}

int ModelBuilder::add_mesh(std::string_view name, const MeshData& mesh, int material) {
    return add_mesh(name, add_geometry(name, mesh), material);
}

int ModelBuilder::add_material(const MaterialSpec& spec) {
    tinygltf::Material m;
    m.name = spec.name;
    m.pbrMetallicRoughness.baseColorFactor = to_doubles(&spec.base_color.x, 4);
    m.pbrMetallicRoughness.metallicFactor = spec.metallic;
    m.pbrMetallicRoughness.roughnessFactor = spec.roughness;
    m.pbrMetallicRoughness.baseColorTexture.index = spec.base_color_texture;
    m.normalTexture.index = spec.normal_texture;
    m.normalTexture.scale = spec.normal_scale;
    m.emissiveFactor = to_doubles(&spec.emissive.x, 3);
    m.alphaMode = alpha_name(spec.alpha);
    m.alphaCutoff = spec.alpha == Alpha::Mask ? spec.alpha_cutoff : 0.5;
    m.doubleSided = spec.double_sided;
    model_.materials.push_back(m);
    return static_cast<int>(model_.materials.size()) - 1;
}

int ModelBuilder::sampler(SamplerKind kind) {
    int& slot = samplers_[kind == SamplerKind::Repeat ? 0 : 1];
    if (slot < 0) {
        tinygltf::Sampler s;
        s.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
        s.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
        const int wrap = kind == SamplerKind::Repeat ? TINYGLTF_TEXTURE_WRAP_REPEAT
                                                     : TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
        s.wrapS = wrap;
        s.wrapT = wrap;
        s.name = kind == SamplerKind::Repeat ? "repeat" : "clamp";
        model_.samplers.push_back(s);
        slot = static_cast<int>(model_.samplers.size()) - 1;
    }
    return slot;
}

int ModelBuilder::add_texture(std::string_view name, const Pixels& pixels, SamplerKind kind) {
    tinygltf::Image image;
    image.name = std::string(name);
    image.uri = image.name + ".png";  // used as the file name by export_model
    image.mimeType = "image/png";
    image.width = pixels.width;
    image.height = pixels.height;
    image.component = 4;
    image.bits = 8;
    image.pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image.image = pixels.rgba;
    model_.images.push_back(std::move(image));

    tinygltf::Texture texture;
    texture.name = std::string(name);
    texture.source = static_cast<int>(model_.images.size()) - 1;
    texture.sampler = sampler(kind);
    model_.textures.push_back(texture);
    return static_cast<int>(model_.textures.size()) - 1;
}

int ModelBuilder::add_node(std::string_view name, int mesh, const Transform& t) {
    tinygltf::Node node;
    node.name = std::string(name);
    node.mesh = mesh;
    // Identity components are left out, as exporters do.
    if (t.translation != glm::vec3(0.0f)) node.translation = to_doubles(&t.translation.x, 3);
    if (t.rotation != glm::quat(1.0f, 0.0f, 0.0f, 0.0f)) {
        node.rotation = {t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w};
    }
    if (t.scale != glm::vec3(1.0f)) node.scale = to_doubles(&t.scale.x, 3);
    model_.nodes.push_back(node);
    return static_cast<int>(model_.nodes.size()) - 1;
}

int ModelBuilder::add_camera(std::string_view name, const CameraSpec& spec, const glm::vec3& eye,
                             const glm::vec3& target, const glm::vec3& up) {
    tinygltf::Camera cam;
    cam.name = std::string(name);
    cam.type = "perspective";
    cam.perspective.yfov = spec.yfov;
    cam.perspective.aspectRatio = spec.aspect;
    cam.perspective.znear = spec.znear;
    cam.perspective.zfar = spec.zfar;
    model_.cameras.push_back(cam);

    const glm::vec3 f = glm::normalize(target - eye);
    const glm::vec3 r = glm::normalize(glm::cross(f, up));
    const glm::vec3 u = glm::cross(r, f);
    Transform t;
    t.translation = eye;
    t.rotation = glm::normalize(glm::quat_cast(glm::mat3(r, u, -f)));  // local -Z = forward
    const int node = add_node(name, -1, t);
    model_.nodes[static_cast<size_t>(node)].camera = static_cast<int>(model_.cameras.size()) - 1;
    return node;
}

tinygltf::Model ModelBuilder::finish(std::string_view scene_name) {
    tinygltf::Scene scene;
    scene.name = std::string(scene_name);
    for (size_t i = 0; i < model_.nodes.size(); ++i) scene.nodes.push_back(static_cast<int>(i));
    model_.scenes = {scene};
    model_.defaultScene = 0;
    model_.buffers[0].name = std::string(scene_name);
    while (model_.buffers[0].data.size() % 4 != 0) model_.buffers[0].data.push_back(0);
    return std::move(model_);
}

}  // namespace ds::scene::builtin
