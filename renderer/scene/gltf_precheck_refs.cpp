#include "renderer/scene/gltf_precheck_refs.h"

#include <string>
#include <string_view>

#include "renderer/scene/gltf_source.h"
#include "renderer/scene/import_util.h"

namespace ds::scene::detail {
namespace {

using nlohmann::json;

std::string at(const char* array, size_t i) {
    return std::string(array) + "[" + std::to_string(i) + "]";
}

const json& array_or_empty(const json& doc, const char* key) {
    static const json empty = json::array();
    const auto it = doc.find(key);
    return it == doc.end() ? empty : *it;
}

// tinygltf's data: URI prefixes (IsDataURI); anything else starting "data:" it would take for
// a file name.
constexpr std::string_view kDataPrefixes[] = {"data:application/octet-stream;base64,",
                                              "data:image/jpeg;base64,",
                                              "data:image/png;base64,",
                                              "data:image/bmp;base64,",
                                              "data:image/gif;base64,",
                                              "data:text/plain;base64,",
                                              "data:application/gltf-buffer;base64,"};

bool is_base64_char(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '+' ||
           c == '/';
}

void check_data_uri(std::string_view uri, const std::string& path, const json* buffer) {
    size_t start = 0;
    for (std::string_view prefix : kDataPrefixes)
        if (uri.starts_with(prefix)) start = prefix.size();
    if (start == 0)
        fail(path +
             ": malformed data: URI (need data:application/octet-stream;base64, or an "
             "image type)");
    const std::string_view data = uri.substr(start);
    size_t end = data.size();
    while (end > 0 && data.size() - end < 2 && data[end - 1] == '=') --end;
    for (size_t i = 0; i < end; ++i)
        if (!is_base64_char(data[i]))
            fail(path + ": malformed data: URI: character " + std::to_string(start + i) +
                 " is not base64");
    const uint64_t decoded = uint64_t{end} * 3 / 4;
    if (buffer && buffer->contains("byteLength") &&
        decoded != (*buffer)["byteLength"].get<uint64_t>())
        fail(path + ": the data: URI holds " + std::to_string(decoded) +
             " bytes, the buffer's byteLength is " +
             std::to_string((*buffer)["byteLength"].get<uint64_t>()));
}

uint64_t uint_or(const json& object, const char* key, uint64_t fallback) {
    const auto it = object.find(key);
    return it == object.end() ? fallback : it->get<uint64_t>();
}

// Buffers and images naming a file; data: URIs are checked here.
std::vector<FileRef> file_refs(const json& doc) {
    std::vector<FileRef> refs;
    for (const char* array : {"buffers", "images"}) {
        const auto it = doc.find(array);
        if (it == doc.end()) continue;
        for (size_t i = 0; i < it->size(); ++i) {
            const auto uri = (*it)[i].find("uri");
            if (uri == (*it)[i].end()) continue;
            const std::string entry = std::string(array) + "[" + std::to_string(i) + "]";
            const std::string path = entry + ".uri";
            if (array == std::string("buffers") && !(*it)[i].contains("byteLength"))
                fail(entry + ".byteLength is missing");
            const auto text = uri->get<std::string>();
            if (text.starts_with("data:"))
                check_data_uri(text, path, array == std::string("buffers") ? &(*it)[i] : nullptr);
            else
                refs.push_back({path, text, decode_uri(text), array == std::string("buffers"),
                                uint_or((*it)[i], "byteLength", 0)});
        }
    }
    return refs;
}

// An image stored in a buffer view: tinygltf passes &buffer.data[byteOffset] and byteLength to
// the image decoder without checking them against the buffer (whose data is byteLength long).
void check_image_views(const json& doc) {
    const auto images = doc.find("images");
    if (images == doc.end()) return;
    const json empty = json::array();
    const json& views = doc.contains("bufferViews") ? doc["bufferViews"] : empty;
    const json& buffers = doc.contains("buffers") ? doc["buffers"] : empty;
    for (size_t i = 0; i < images->size(); ++i) {
        const json& image = (*images)[i];
        if (!image.contains("bufferView")) continue;
        const std::string path = "images[" + std::to_string(i) + "].bufferView";
        const uint64_t v = image["bufferView"].get<uint64_t>();
        if (v >= views.size()) fail(path + ": buffer view " + std::to_string(v) + " out of range");
        const json& view = views[v];
        const uint64_t b = uint_or(view, "buffer", UINT64_MAX);
        if (b >= buffers.size())
            fail(path + ": bufferViews[" + std::to_string(v) + "].buffer out of range");
        const uint64_t offset = uint_or(view, "byteOffset", 0);
        const uint64_t length = uint_or(view, "byteLength", 0);
        const uint64_t size = uint_or(buffers[b], "byteLength", 0);
        if (length == 0 || offset > size || length > size - offset)
            fail(path + ": bufferViews[" + std::to_string(v) + "] (byteOffset " +
                 std::to_string(offset) + ", byteLength " + std::to_string(length) +
                 ") does not lie inside buffers[" + std::to_string(b) + "] (" +
                 std::to_string(size) + " bytes)");
    }
}

// glTF 2.0 3.6.2.2 and 5.11: a stride is a multiple of 4 in 4..252.
void check_strides(const json& doc) {
    const json& views = array_or_empty(doc, "bufferViews");
    for (size_t i = 0; i < views.size(); ++i) {
        const auto stride = views[i].find("byteStride");
        if (stride == views[i].end()) continue;
        const uint64_t value = stride->get<uint64_t>();
        if (value < 4 || value > 252 || value % 4 != 0)
            fail(at("bufferViews", i) + ".byteStride " + std::to_string(value) +
                 ": must be a multiple of 4 in 4..252");
    }
}

void check_accessor_types(const json& doc) {
    static const std::string_view kTypes[] = {"SCALAR", "VEC2", "VEC3", "VEC4",
                                              "MAT2",   "MAT3", "MAT4"};
    const json& accessors = array_or_empty(doc, "accessors");
    for (size_t i = 0; i < accessors.size(); ++i) {
        const auto type = accessors[i].find("type");
        if (type == accessors[i].end()) fail(at("accessors", i) + ".type is missing");
        const auto text = type->get<std::string>();
        bool known = false;
        for (std::string_view t : kTypes) known = known || t == text;
        if (!known) fail(at("accessors", i) + ".type " + quote_value(text) + " is not a glTF type");
    }
}

// tinygltf reports a bad accessor index of a primitive without saying which primitive.
void check_primitive_refs(const json& doc) {
    const size_t accessors = array_or_empty(doc, "accessors").size();
    const json& meshes = array_or_empty(doc, "meshes");
    for (size_t m = 0; m < meshes.size(); ++m) {
        const json& primitives = array_or_empty(meshes[m], "primitives");
        for (size_t p = 0; p < primitives.size(); ++p) {
            const std::string path = at("meshes", m) + ".primitives[" + std::to_string(p) + "]";
            auto check = [&](const json& index, const std::string& what) {
                if (index.get<uint64_t>() >= accessors)
                    fail(path + what + ": accessor " + std::to_string(index.get<uint64_t>()) +
                         " out of range (" + std::to_string(accessors) + " accessors)");
            };
            if (const auto it = primitives[p].find("indices"); it != primitives[p].end())
                check(*it, ".indices");
            for (const auto& [name, index] : array_or_empty(primitives[p], "attributes").items())
                check(index, ".attributes." + one_line(name));
        }
    }
}

}  // namespace

std::vector<FileRef> check_references(const json& doc) {
    check_strides(doc);
    check_accessor_types(doc);
    check_primitive_refs(doc);
    check_image_views(doc);
    return file_refs(doc);
}

}  // namespace ds::scene::detail
