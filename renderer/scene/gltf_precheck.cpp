#include "renderer/scene/gltf_precheck.h"

#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include <nlohmann/json.hpp>

#include "renderer/scene/gltf_json_scan.h"
#include "renderer/scene/gltf_precheck_refs.h"
#include "renderer/scene/import_util.h"

namespace ds::scene::detail {
namespace {

using nlohmann::json;

// Core glTF nests ~8 levels; anything far deeper is not glTF (and would cost stack). The byte
// scan has already bounded the whole document; this bound is kept for the walk's own sake.
constexpr int kMaxDepth = 64;
constexpr uint32_t kGlbChunkJson = 0x4E4F534A;  // "JSON"
constexpr size_t kGlbJsonOffset = 20;

uint32_t read_u32(std::string_view bytes, size_t offset) {
    const auto* p = reinterpret_cast<const unsigned char*>(bytes.data() + offset);
    return uint32_t{p[0]} | uint32_t{p[1]} << 8 | uint32_t{p[2]} << 16 | uint32_t{p[3]} << 24;
}

json parse_json(std::string_view text, size_t base) {
    text = without_padding(text);
    try {
        return json::parse(text);
    } catch (const json::exception& e) {
        std::string what = e.what();
        if (const size_t bracket = what.find("] "); what.starts_with("[") && bracket != what.npos)
            what = what.substr(bracket + 2);  // drop "[json.exception.parse_error.101] "
        // A parse error knows its byte (1-based); a number out of range only its text.
        size_t at = std::string::npos;
        if (const auto* parse = dynamic_cast<const json::parse_error*>(&e); parse && parse->byte)
            at = parse->byte - 1;
        const size_t quote = what.find("parsing '");
        if (at == std::string::npos && quote != std::string::npos) {
            const size_t start = quote + 9;
            at = text.find(what.substr(start, what.find('\'', start) - start));
        }
        if (at != std::string::npos)
            fail("byte " + std::to_string(base + at) + ": invalid JSON: " + what);
        fail("invalid JSON: " + what);
    }
}

void check_version(const json& doc) {
    const auto asset = doc.find("asset");
    if (asset == doc.end() || !asset->is_object()) fail(version_message(""));
    const auto version = asset->find("version");
    if (version == asset->end()) fail(version_message(""));
    if (version->is_number()) fail(version_message(version->dump()));
    if (!version->is_string()) fail("asset.version must be a string");
    const auto text = version->get<std::string>();
    if (!is_supported_version(text)) fail(version_message(one_line(text)));
}

void check_required_extensions(const json& doc) {
    const auto required = doc.find("extensionsRequired");
    if (required == doc.end()) return;
    if (!required->is_array()) fail("extensionsRequired must be an array");
    for (const json& name : *required) {
        if (!name.is_string()) fail("extensionsRequired must hold strings");
        const auto text = name.get<std::string>();
        if (!is_supported_required_extension(text)) fail(unsupported_extension_message(text));
    }
}

enum class Kind {
    String,
    Uint,
    Number,
    Bool,
    Object,
    Array,
    UintArray,
    NumberArray,
    ObjectArray,
    // An accessor's min and max: numbers, or null where a writer had none (gltf-pipeline's
    // Draco output without position quantization). The importer reads the data, never these.
    BoundsArray,
};

// The JSON kind of a core property, from its key and the key its object sits under (array
// elements inherit the array's key). Unknown keys are not checked.
std::optional<Kind> expected_kind(std::string_view parent, std::string_view key) {
    if (parent == "attributes" || parent == "targets") return Kind::Uint;  // -> accessor
    if (parent == "sparse" && (key == "indices" || key == "values")) return Kind::Object;
    if (parent == "channels" && key == "target") return Kind::Object;
    if (parent == "nodes" && key == "scale") return Kind::NumberArray;
    if (parent == "accessors" && (key == "min" || key == "max")) return Kind::BoundsArray;
    if (key == "nodes") return parent.empty() ? Kind::ObjectArray : Kind::UintArray;
    static const std::unordered_map<std::string_view, Kind> kRules = [] {
        std::unordered_map<std::string_view, Kind> rules;
        auto add = [&](Kind kind, std::initializer_list<std::string_view> keys) {
            for (std::string_view k : keys) rules.emplace(k, kind);
        };
        add(Kind::String, {"name", "uri", "mimeType", "generator", "version", "minVersion",
                           "copyright", "type", "alphaMode", "interpolation", "path"});
        add(Kind::Uint, {"scene",      "buffer",
                         "bufferView", "byteOffset",
                         "byteLength", "byteStride",
                         "count",      "componentType",
                         "index",      "texCoord",
                         "mesh",       "camera",
                         "skin",       "material",
                         "mode",       "indices",
                         "source",     "sampler",
                         "magFilter",  "minFilter",
                         "wrapS",      "wrapT",
                         "input",      "output",
                         "node",       "inverseBindMatrices",
                         "skeleton",   "target"});
        add(Kind::Number, {"scale", "strength", "alphaCutoff", "metallicFactor", "roughnessFactor",
                           "aspectRatio", "yfov", "zfar", "znear", "xmag", "ymag"});
        add(Kind::Bool, {"normalized", "doubleSided"});
        add(Kind::Object, {"asset", "pbrMetallicRoughness", "normalTexture", "occlusionTexture",
                           "emissiveTexture", "baseColorTexture", "metallicRoughnessTexture",
                           "attributes", "sparse", "perspective", "orthographic"});
        add(Kind::UintArray, {"children", "joints"});
        add(Kind::NumberArray, {"matrix", "rotation", "translation", "weights", "min", "max",
                                "baseColorFactor", "emissiveFactor"});
        add(Kind::ObjectArray, {"accessors", "animations", "buffers", "bufferViews", "cameras",
                                "images", "materials", "meshes", "samplers", "scenes", "skins",
                                "textures", "primitives", "channels", "targets"});
        add(Kind::Array, {"extensionsUsed", "extensionsRequired"});
        return rules;
    }();
    const auto it = kRules.find(key);
    return it == kRules.end() ? std::nullopt : std::optional<Kind>(it->second);
}

bool is_uint(const json& v) {
    return v.is_number_unsigned();
}

bool all_of(const json& array, bool (*test)(const json&)) {
    for (const json& v : array)
        if (!test(v)) return false;
    return true;
}

bool matches(const json& v, Kind kind) {
    switch (kind) {
        case Kind::String:
            return v.is_string();
        case Kind::Uint:
            return is_uint(v);
        case Kind::Number:
            return v.is_number();
        case Kind::Bool:
            return v.is_boolean();
        case Kind::Object:
            return v.is_object();
        case Kind::Array:
            return v.is_array();
        case Kind::UintArray:
            return v.is_array() && all_of(v, is_uint);
        case Kind::NumberArray:
            return v.is_array() && all_of(v, [](const json& e) { return e.is_number(); });
        case Kind::ObjectArray:
            return v.is_array() && all_of(v, [](const json& e) { return e.is_object(); });
        case Kind::BoundsArray:
            return v.is_array() &&
                   all_of(v, [](const json& e) { return e.is_number() || e.is_null(); });
    }
    return false;
}

const char* kind_text(Kind kind) {
    switch (kind) {
        case Kind::String:
            return "a string";
        case Kind::Uint:
            return "a non-negative integer";
        case Kind::Number:
            return "a number";
        case Kind::Bool:
            return "a boolean";
        case Kind::Object:
            return "an object";
        case Kind::Array:
            return "an array";
        case Kind::UintArray:
            return "an array of non-negative integers";
        case Kind::NumberArray:
        case Kind::BoundsArray:
            return "an array of numbers";
        case Kind::ObjectArray:
            return "an array of objects";
    }
    return "?";
}

// Extension contents follow their own schemas (not checked); each must be an object.
void check_extensions(const json& value, const std::string& path) {
    if (!value.is_object()) fail(path + " must be an object");
    for (const auto& [name, extension] : value.items())
        if (!extension.is_object()) fail(path + "." + name + " must be an object");
}

void check_value(const json& value, std::string_view key, const std::string& path, int depth);

void check_object(const json& object, std::string_view parent, const std::string& path, int depth) {
    if (depth > kMaxDepth) fail("JSON nested too deeply at " + path);
    for (const auto& [key, value] : object.items()) {
        const std::string here = path.empty() ? key : path + "." + key;
        if (key == "extras") continue;  // free-form application data
        if (key == "extensions") {
            check_extensions(value, here);
            continue;
        }
        if (const auto kind = expected_kind(parent, key); kind && !matches(value, *kind))
            fail(here + " must be " + kind_text(*kind));
        check_value(value, key, here, depth + 1);
    }
}

void check_value(const json& value, std::string_view key, const std::string& path, int depth) {
    if (depth > kMaxDepth) fail("JSON nested too deeply at " + path);
    if (value.is_object()) {
        check_object(value, key, path, depth);
    } else if (value.is_array()) {
        for (size_t i = 0; i < value.size(); ++i)
            if (value[i].is_structured())
                check_value(value[i], key, path + "[" + std::to_string(i) + "]", depth + 1);
    }
}

}  // namespace

std::string_view glb_json_chunk(std::string_view bytes) {
    if (bytes.size() < 12) fail("truncated GLB header");
    const uint32_t version = read_u32(bytes, 4);
    if (version == 1) fail(version_message("1.0"));  // binary glTF 1.0 (KHR_binary_glTF)
    if (version != 2) fail("unsupported GLB container version " + std::to_string(version));
    if (bytes.size() < 20) fail("truncated GLB: no JSON chunk");
    const uint32_t length = read_u32(bytes, 12);
    if (read_u32(bytes, 16) != kGlbChunkJson) fail("GLB: the first chunk is not JSON");
    if (length > bytes.size() - 20) fail("GLB: JSON chunk runs past the end of the file");
    return bytes.substr(kGlbJsonOffset, length);
}

std::string_view without_padding(std::string_view text) {
    while (!text.empty() && (text.back() == '\0' || text.back() == ' ')) text.remove_suffix(1);
    return text;
}

std::vector<FileRef> precheck_gltf(std::string_view bytes, bool binary) {
    const std::string_view text = binary ? glb_json_chunk(bytes) : bytes;
    scan_json_limits(text, binary ? kGlbJsonOffset : 0);
    const json doc = parse_json(text, binary ? kGlbJsonOffset : 0);
    if (!doc.is_object()) fail("not a glTF file: the JSON top level is not an object");
    check_version(doc);
    check_required_extensions(doc);
    check_object(doc, "", "", 0);
    return check_references(doc);
}

}  // namespace ds::scene::detail
