// KHR_draco_mesh_compression: a primitive's Draco stream decoded into the placeholder
// bufferViews of its accessors (gltf_prepare.cpp made them, sized from each accessor).
#include <cstring>
#include <memory>
#include <vector>

#include <draco/compression/decode.h>

#include "renderer/scene/gltf_accessor.h"
#include "renderer/scene/gltf_decode.h"
#include "renderer/scene/import_util.h"

namespace ds::scene::detail {
namespace {

// Where an accessor's elements go: checked against its bufferView and buffer.
struct Target {
    unsigned char* data = nullptr;
    size_t stride = 0, count = 0, components = 0, component_size = 0;
    int type = 0;
};

// The accessor's bytes, when they lie in a placeholder buffer (else: nothing to fill).
std::optional<Target> placeholder_target(tinygltf::Model& model, int index,
                                         const std::map<std::string, uint64_t>& placeholders,
                                         const std::string& what) {
    if (index < 0 || size_t(index) >= model.accessors.size()) return std::nullopt;
    const tinygltf::Accessor& a = model.accessors[size_t(index)];
    if (a.bufferView < 0 || size_t(a.bufferView) >= model.bufferViews.size()) return std::nullopt;
    const tinygltf::BufferView& view = model.bufferViews[size_t(a.bufferView)];
    if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size()) return std::nullopt;
    tinygltf::Buffer& buffer = model.buffers[size_t(view.buffer)];
    if (!placeholders.contains(buffer.uri)) return std::nullopt;
    Target t;
    t.type = a.componentType;
    t.component_size = component_size(a.componentType);
    t.components = size_t(tinygltf::GetNumComponentsInType(uint32_t(a.type)));
    t.count = a.count;
    t.stride = view.byteStride ? view.byteStride : t.component_size * t.components;
    if (t.component_size == 0 || t.components == 0 || t.components > 4 || t.count == 0)
        fail(what + ": a Draco accessor needs a SCALAR or VECn type and a component type");
    const uint64_t span = uint64_t(t.count - 1) * t.stride + t.component_size * t.components;
    if (view.byteOffset > buffer.data.size() ||
        view.byteLength > buffer.data.size() - view.byteOffset || a.byteOffset > view.byteLength ||
        span > view.byteLength - a.byteOffset)
        fail(what + ": the accessor does not fit its bufferView");
    t.data = buffer.data.data() + view.byteOffset + a.byteOffset;
    return t;
}

template <typename T>
void write_values(const draco::PointAttribute& attribute, Target& t, const std::string& what) {
    T value[4];
    for (size_t i = 0; i < t.count; ++i) {
        const draco::AttributeValueIndex v = attribute.mapped_index(draco::PointIndex(uint32_t(i)));
        if (v.value() >= attribute.size() ||
            !attribute.ConvertValue<T>(v, int8_t(t.components), value))
            fail(what + ": point " + std::to_string(i) + " has no value of this type");
        std::memcpy(t.data + i * t.stride, value, sizeof(T) * t.components);
    }
}

void write_attribute(const draco::PointAttribute& attribute, const draco::Mesh& mesh, Target& t,
                     const std::string& what) {
    if (t.count != mesh.num_points())
        fail(what + ": the accessor's count is " + std::to_string(t.count) +
             ", the Draco mesh has " + std::to_string(mesh.num_points()) + " points");
    if (size_t(attribute.num_components()) != t.components)
        fail(what + ": the accessor has " + std::to_string(t.components) +
             " components, the Draco attribute " + std::to_string(attribute.num_components()));
    switch (t.type) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return write_values<float>(attribute, t, what);
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            return write_values<int8_t>(attribute, t, what);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return write_values<uint8_t>(attribute, t, what);
        case TINYGLTF_COMPONENT_TYPE_SHORT:
            return write_values<int16_t>(attribute, t, what);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return write_values<uint16_t>(attribute, t, what);
        default:
            return write_values<uint32_t>(attribute, t, what);
    }
}

void write_indices(const draco::Mesh& mesh, Target& t, const std::string& what) {
    if (t.components != 1 || t.count != size_t(mesh.num_faces()) * 3)
        fail(what + ": the indices accessor has " + std::to_string(t.count) +
             " elements, the Draco mesh " + std::to_string(mesh.num_faces()) + " triangles");
    const uint64_t max = t.component_size == 1 ? 0xff : t.component_size == 2 ? 0xffff : 0xffffffff;
    for (uint32_t f = 0; f < mesh.num_faces(); ++f)
        for (int corner = 0; corner < 3; ++corner) {
            const uint32_t index = mesh.face(draco::FaceIndex(f))[corner].value();
            if (index > max) fail(what + ": index " + std::to_string(index) + " does not fit");
            unsigned char* p = t.data + (size_t(f) * 3 + size_t(corner)) * t.stride;
            if (t.component_size == 1) *p = uint8_t(index);
            if (t.component_size == 2) {
                const uint16_t v = uint16_t(index);
                std::memcpy(p, &v, 2);
            }
            if (t.component_size == 4) std::memcpy(p, &index, 4);
        }
}

std::unique_ptr<draco::Mesh> decode_stream(const tinygltf::Model& model, const tinygltf::Value& ext,
                                           const std::string& what) {
    if (!ext.IsObject() || !ext.Has("bufferView") || !ext.Get("bufferView").IsInt())
        fail(what + ": no bufferView");
    const int index = ext.Get("bufferView").GetNumberAsInt();
    if (index < 0 || size_t(index) >= model.bufferViews.size())
        fail(what + ": bufferView " + std::to_string(index) + " out of range");
    const tinygltf::BufferView& view = model.bufferViews[size_t(index)];
    if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size())
        fail(what + ": the bufferView's buffer is out of range");
    const std::vector<unsigned char>& data = model.buffers[size_t(view.buffer)].data;
    if (view.byteLength == 0 || view.byteOffset > data.size() ||
        view.byteLength > data.size() - view.byteOffset)
        fail(what + ": the bufferView lies outside its buffer");
    draco::DecoderBuffer buffer;
    buffer.Init(reinterpret_cast<const char*>(data.data() + view.byteOffset), view.byteLength);
    const auto type = draco::Decoder::GetEncodedGeometryType(&buffer);
    if (!type.ok() || type.value() != draco::TRIANGULAR_MESH)
        fail(what + ": not a Draco triangle mesh" +
             (type.ok() ? "" : " (" + type.status().error_msg_string() + ")"));
    draco::Decoder decoder;
    auto mesh = decoder.DecodeMeshFromBuffer(&buffer);
    if (!mesh.ok())
        fail(what + ": the Draco stream does not decode (" + mesh.status().error_msg_string() +
             ")");
    return std::move(mesh).value();
}

void decode_primitive(tinygltf::Model& model, tinygltf::Primitive& primitive,
                      const std::map<std::string, uint64_t>& placeholders,
                      const std::string& what) {
    const tinygltf::Value& ext = primitive.extensions.at(kDracoExtension);
    std::vector<std::pair<std::string, Target>> targets;
    if (ext.IsObject() && ext.Has("attributes") && ext.Get("attributes").IsObject())
        for (const std::string& name : ext.Get("attributes").Keys()) {
            const auto accessor = primitive.attributes.find(name);
            if (accessor == primitive.attributes.end()) continue;
            if (auto t =
                    placeholder_target(model, accessor->second, placeholders, what + " " + name))
                targets.emplace_back(name, *t);
        }
    auto indices = placeholder_target(model, primitive.indices, placeholders, what + " indices");
    if (targets.empty() && !indices) return;  // the file holds every accessor uncompressed too
    const std::unique_ptr<draco::Mesh> mesh = decode_stream(model, ext, what);
    for (auto& [name, target] : targets) {
        const tinygltf::Value& id = ext.Get("attributes").Get(name);
        if (!id.IsInt() || id.GetNumberAsInt() < 0)
            fail(what + ": attribute " + name + " needs a non-negative id");
        const draco::PointAttribute* attribute =
            mesh->GetAttributeByUniqueId(uint32_t(id.GetNumberAsInt()));
        if (!attribute)
            fail(what + ": the Draco mesh has no attribute " + std::to_string(id.GetNumberAsInt()));
        write_attribute(*attribute, *mesh, target, what + " " + name);
    }
    if (indices) write_indices(*mesh, *indices, what + " indices");
}

}  // namespace

void decode_draco(tinygltf::Model& model, const std::map<std::string, uint64_t>& placeholders) {
    for (size_t m = 0; m < model.meshes.size(); ++m)
        for (size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
            tinygltf::Primitive& primitive = model.meshes[m].primitives[p];
            if (!primitive.extensions.contains(kDracoExtension)) continue;
            decode_primitive(model, primitive, placeholders,
                             "mesh " + std::to_string(m) + " primitive " + std::to_string(p) + " " +
                                 kDracoExtension);
        }
}

}  // namespace ds::scene::detail
