#include "renderer/scene/gltf_prepare.h"

#include <set>

#include <nlohmann/json.hpp>

#include "renderer/scene/gltf_accessor.h"
#include "renderer/scene/gltf_precheck.h"
#include "renderer/scene/import_limits.h"
#include "renderer/scene/import_util.h"

namespace ds::scene::detail {
namespace {

using nlohmann::json;

// Placeholder uris: a scheme no file next to a document has, numbered within the document.
class Placeholders {
  public:
    explicit Placeholders(Prepared& out) : out_(out) {}
    std::string add(uint64_t size, const std::string& what) {
        if (size == 0 || size > limits::kMaxFileBytes - total_)
            fail(what + ": decoded data of " + std::to_string(size) +
                 " bytes is beyond the limit of " + std::to_string(limits::kMaxFileBytes));
        total_ += size;
        std::string uri = "depthscope:placeholder/" + std::to_string(out_.placeholders.size());
        out_.placeholders[uri] = size;
        return uri;
    }

  private:
    Prepared& out_;
    uint64_t total_ = 0;
};

const json* extension(const json& object, const char* name) {
    const auto extensions = object.find("extensions");
    if (extensions == object.end() || !extensions->is_object()) return nullptr;
    const auto found = extensions->find(name);
    return found != extensions->end() && found->is_object() ? &*found : nullptr;
}

// A fallback buffer without data gets a placeholder (a GLB's buffer 0 is its BIN chunk).
bool fill_meshopt_fallbacks(json& doc, bool binary, Placeholders& placeholders) {
    bool changed = false;
    auto buffers = doc.find("buffers");
    if (buffers == doc.end() || !buffers->is_array()) return false;
    for (size_t i = binary ? 1 : 0; i < buffers->size(); ++i) {
        json& buffer = (*buffers)[i];
        if (!buffer.is_object() || buffer.contains("uri") || !extension(buffer, kMeshoptExtension))
            continue;
        const auto length = buffer.find("byteLength");
        if (length == buffer.end() || !length->is_number_unsigned()) continue;  // tinygltf says
        const std::string what =
            "buffers[" + std::to_string(i) + "] (" + kMeshoptExtension + " fallback)";
        buffer["uri"] = placeholders.add(length->get<uint64_t>(), what);
        changed = true;
    }
    return changed;
}

// Bytes of a non-matrix accessor (Draco fills attributes and indices, never matrices).
uint64_t accessor_bytes(const json& accessor, const std::string& what) {
    const auto count = accessor.find("count");
    const auto component = accessor.find("componentType");
    const auto type = accessor.find("type");
    if (count == accessor.end() || !count->is_number_unsigned() || component == accessor.end() ||
        !component->is_number_integer() || type == accessor.end() || !type->is_string())
        fail(what + ": a Draco accessor needs count, componentType and type");
    const uint64_t n = count->get<uint64_t>();
    if (n == 0 || n > limits::kMaxAccessorElements)
        fail(what + ": count " + std::to_string(n) + " is out of range");
    const uint64_t size = component_size(component->get<int>());
    if (size == 0) fail(what + ": invalid componentType");
    const std::string t = type->get<std::string>();
    const uint64_t components = t == "SCALAR" ? 1 : t == "VEC2" ? 2 : t == "VEC3" ? 3 : 4;
    return n * size * components;
}

// The accessors a primitive's Draco stream fills: its extension's attributes, and its indices.
std::set<size_t> draco_accessors(const json& primitive, const json& draco, size_t count) {
    std::set<size_t> out;
    const auto attributes = primitive.find("attributes");
    const auto named = draco.find("attributes");
    if (attributes != primitive.end() && attributes->is_object() && named != draco.end() &&
        named->is_object())
        for (const auto& [name, id] : named->items()) {
            const auto accessor = attributes->find(name);
            if (accessor != attributes->end() && accessor->is_number_unsigned() &&
                accessor->get<uint64_t>() < count)
                out.insert(accessor->get<size_t>());
        }
    const auto indices = primitive.find("indices");
    if (indices != primitive.end() && indices->is_number_unsigned() &&
        indices->get<uint64_t>() < count)
        out.insert(indices->get<size_t>());
    return out;
}

// Accessors without a bufferView that a Draco stream fills get one in a new placeholder buffer.
bool add_draco_views(json& doc, Placeholders& placeholders) {
    const auto meshes = doc.find("meshes");
    auto accessors = doc.find("accessors");
    if (meshes == doc.end() || !meshes->is_array() || accessors == doc.end() ||
        !accessors->is_array())
        return false;
    std::set<size_t> filled;
    for (const json& mesh : *meshes) {
        const auto primitives = mesh.is_object() ? mesh.find("primitives") : mesh.end();
        if (primitives == mesh.end() || !primitives->is_array()) continue;
        for (const json& primitive : *primitives)
            if (const json* draco =
                    primitive.is_object() ? extension(primitive, kDracoExtension) : nullptr)
                for (size_t a : draco_accessors(primitive, *draco, accessors->size()))
                    if ((*accessors)[a].is_object() && !(*accessors)[a].contains("bufferView"))
                        filled.insert(a);
    }
    if (filled.empty()) return false;
    json& views = doc["bufferViews"];
    if (!views.is_array()) views = json::array();
    json& buffers = doc["buffers"];
    if (!buffers.is_array()) buffers = json::array();
    uint64_t offset = 0;
    for (size_t a : filled) {
        const uint64_t bytes =
            accessor_bytes((*accessors)[a], "accessors[" + std::to_string(a) + "]");
        (*accessors)[a]["bufferView"] = views.size();
        views.push_back(
            {{"buffer", buffers.size()}, {"byteOffset", offset}, {"byteLength", bytes}});
        offset += (bytes + 3) / 4 * 4;              // each view 4-byte aligned
        if (offset > limits::kMaxFileBytes) break;  // Placeholders::add refuses it
    }
    buffers.push_back(
        {{"byteLength", offset},
         {"uri", placeholders.add(offset, std::string(kDracoExtension) + " accessors")}});
    return true;
}

void put_u32(std::string& out, uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(char((v >> (8 * i)) & 0xff));
}

// The GLB again with a new JSON chunk (padded with spaces) and the chunks after it unchanged.
std::string rebuild_glb(std::string_view bytes, std::string_view old_json, std::string text) {
    text.resize((text.size() + 3) / 4 * 4, ' ');
    const std::string_view rest =
        bytes.substr(size_t(old_json.data() - bytes.data()) + old_json.size());
    const uint64_t total = 12 + 8 + text.size() + rest.size();
    if (total > limits::kMaxFileBytes) fail("the rewritten GLB is larger than the limit");
    std::string out(bytes.substr(0, 8));  // magic and version
    put_u32(out, uint32_t(total));
    put_u32(out, uint32_t(text.size()));
    put_u32(out, 0x4E4F534A);  // "JSON"
    out += text;
    out += rest;
    return out;
}

}  // namespace

Prepared prepare_compressed(std::string_view bytes, bool binary) {
    const std::string_view text = binary ? glb_json_chunk(bytes) : bytes;
    if (text.find(kMeshoptExtension) == text.npos && text.find(kDracoExtension) == text.npos)
        return {};
    // Parsed a second time (precheck_gltf parsed it), only for files that name a compression.
    json doc = json::parse(without_padding(text));
    Prepared out;
    Placeholders placeholders(out);
    const bool meshopt = fill_meshopt_fallbacks(doc, binary, placeholders);
    const bool draco = add_draco_views(doc, placeholders);
    if (!meshopt && !draco) return {};
    out.bytes = binary ? rebuild_glb(bytes, text, doc.dump()) : doc.dump();
    return out;
}

uint64_t PlaceholderSource::check(const std::string& uri) const {
    const auto found = sizes_.find(uri);
    return found != sizes_.end() ? found->second : inner_.check(uri);
}

std::string PlaceholderSource::read(const std::string& uri) const {
    const auto found = sizes_.find(uri);
    return found != sizes_.end() ? std::string(found->second, '\0') : inner_.read(uri);
}

}  // namespace ds::scene::detail
