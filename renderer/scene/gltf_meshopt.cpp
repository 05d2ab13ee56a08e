// EXT_meshopt_compression: bufferViews decoded into their placeholder fallback buffer.
#include <cmath>
#include <cstring>
#include <vector>

#include <meshoptimizer.h>

#include "renderer/scene/gltf_decode.h"
#include "renderer/scene/import_limits.h"
#include "renderer/scene/import_util.h"

namespace ds::scene::detail {
namespace {

struct MeshoptView {
    size_t source = 0;  // the buffer holding the compressed stream
    uint64_t offset = 0, length = 0, stride = 0, count = 0;
    std::string mode, filter;
};

uint64_t number(const tinygltf::Value& ext, const char* key, const std::string& what,
                const uint64_t* fallback = nullptr) {
    if (!ext.Has(key)) {
        if (fallback) return *fallback;
        fail(what + ": no " + key);
    }
    const tinygltf::Value& v = ext.Get(key);
    const double d = v.IsNumber() ? v.GetNumberAsDouble() : -1.0;
    if (!(d >= 0.0 && d <= double(limits::kMaxFileBytes) && d == std::floor(d)))
        fail(what + ": " + key + " must be an integer in 0.." +
             std::to_string(limits::kMaxFileBytes));
    return uint64_t(d);
}

std::string text(const tinygltf::Value& ext, const char* key, const std::string& what,
                 const char* fallback) {
    if (!ext.Has(key)) {
        if (fallback) return fallback;
        fail(what + ": no " + key);
    }
    const tinygltf::Value& v = ext.Get(key);
    if (!v.IsString()) fail(what + ": " + key + " must be a string");
    return v.Get<std::string>();
}

MeshoptView read_view(const tinygltf::Value& ext, const std::string& what) {
    if (!ext.IsObject()) fail(what + " must be an object");
    const uint64_t zero = 0;
    MeshoptView v;
    v.source = size_t(number(ext, "buffer", what));
    v.offset = number(ext, "byteOffset", what, &zero);
    v.length = number(ext, "byteLength", what);
    v.stride = number(ext, "byteStride", what);
    v.count = number(ext, "count", what);
    v.mode = text(ext, "mode", what, nullptr);
    v.filter = text(ext, "filter", what, "NONE");
    return v;
}

// The extension's rules, and meshoptimizer 0.18's asserts, before any decoder runs.
void check_view(const MeshoptView& v, const std::string& what) {
    const std::string at = what + ": ";
    if (v.count == 0) fail(at + "count is 0");
    if (v.mode == "ATTRIBUTES") {
        if (v.stride == 0 || v.stride > 256 || v.stride % 4 != 0)
            fail(at + "ATTRIBUTES needs a byteStride of 4..256, a multiple of 4 (it is " +
                 std::to_string(v.stride) + ")");
    } else if (v.mode == "TRIANGLES" || v.mode == "INDICES") {
        if (v.stride != 2 && v.stride != 4)
            fail(at + v.mode + " needs a byteStride of 2 or 4 (it is " + std::to_string(v.stride) +
                 ")");
        if (v.mode == "TRIANGLES" && v.count % 3 != 0)
            fail(at + "TRIANGLES needs a count that is a multiple of 3 (it is " +
                 std::to_string(v.count) + ")");
    } else {
        fail(at + "unknown mode " + quote_value(v.mode));
    }
    const bool attributes = v.mode == "ATTRIBUTES";
    if (v.filter == "NONE") return;
    if (!attributes) fail(at + "filter " + v.filter + " needs mode ATTRIBUTES");
    if (v.filter == "OCTAHEDRAL" && v.stride != 4 && v.stride != 8)
        fail(at + "OCTAHEDRAL needs a byteStride of 4 or 8");
    else if (v.filter == "QUATERNION" && v.stride != 8)
        fail(at + "QUATERNION needs a byteStride of 8");
    else if (v.filter != "OCTAHEDRAL" && v.filter != "QUATERNION" && v.filter != "EXPONENTIAL")
        fail(at + "unknown filter " + quote_value(v.filter));
}

// Decodes into `out` (4-byte aligned, count × stride bytes): meshopt writes typed elements.
void decode_view(const MeshoptView& v, const unsigned char* data, std::vector<uint32_t>& out,
                 const std::string& what) {
    int rc = 0;
    if (v.mode == "ATTRIBUTES")
        rc = meshopt_decodeVertexBuffer(out.data(), v.count, v.stride, data, v.length);
    else if (v.mode == "TRIANGLES")
        rc = meshopt_decodeIndexBuffer(out.data(), v.count, v.stride, data, v.length);
    else
        rc = meshopt_decodeIndexSequence(out.data(), v.count, v.stride, data, v.length);
    if (rc != 0)
        fail(what + ": the " + v.mode + " stream does not decode (meshoptimizer " +
             std::to_string(rc) +
             (v.length > 0 && data[0] & 0x0f ? "; a codec version after 0" : "") + ")");
    if (v.filter == "OCTAHEDRAL") meshopt_decodeFilterOct(out.data(), v.count, v.stride);
    if (v.filter == "QUATERNION") meshopt_decodeFilterQuat(out.data(), v.count, v.stride);
    if (v.filter == "EXPONENTIAL") meshopt_decodeFilterExp(out.data(), v.count, v.stride);
}

}  // namespace

void decode_meshopt(tinygltf::Model& model, const std::map<std::string, uint64_t>& placeholders) {
    for (size_t i = 0; i < model.bufferViews.size(); ++i) {
        const tinygltf::BufferView& view = model.bufferViews[i];
        const auto ext = view.extensions.find(kMeshoptExtension);
        if (ext == view.extensions.end()) continue;
        if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size())
            continue;  // checked later
        tinygltf::Buffer& target = model.buffers[size_t(view.buffer)];
        if (!placeholders.contains(target.uri)) continue;  // the file holds the data too
        const std::string what = "bufferViews[" + std::to_string(i) + "]." + kMeshoptExtension;
        const MeshoptView v = read_view(ext->second, what);
        check_view(v, what);
        if (v.source >= model.buffers.size())
            fail(what + ": buffer " + std::to_string(v.source) + " out of range");
        const std::vector<unsigned char>& source = model.buffers[v.source].data;
        if (v.offset > source.size() || v.length > source.size() - v.offset || v.length == 0)
            fail(what + ": bytes " + std::to_string(v.offset) + "+" + std::to_string(v.length) +
                 " are outside buffer " + std::to_string(v.source) + " (" +
                 std::to_string(source.size()) + " bytes)");
        const uint64_t bytes = v.count * v.stride;
        if (bytes != view.byteLength)
            fail(what + ": count × byteStride is " + std::to_string(bytes) +
                 " bytes, the bufferView's byteLength " + std::to_string(view.byteLength));
        if (view.byteOffset > target.data.size() || bytes > target.data.size() - view.byteOffset)
            fail(what + ": the bufferView lies outside its buffer");
        std::vector<uint32_t> out(size_t((bytes + 3) / 4));
        decode_view(v, source.data() + v.offset, out, what);
        std::memcpy(target.data.data() + view.byteOffset, out.data(), size_t(bytes));
    }
}

}  // namespace ds::scene::detail
