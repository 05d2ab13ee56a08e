// Malformed corpus, part 1: edits of the glTF JSON (counts, offsets, strides, indices, the node
// hierarchy, nesting, numbers, cameras, extensions, uris). The valid export's facts used here:
// accessor 0 is the ground's POSITION (VEC3 float, 4 elements, all of bufferView 0), accessor 4
// its indices (SCALAR unsigned int), node 1 places mesh 0, images 0-2 are PNG files.
#include <sys/stat.h>

#include "malformed_corpus.h"

namespace ds::test::corpus {
namespace {

using Edit = std::function<void(json&)>;

// A case that edits the document and writes it as scene.gltf.
Case edit(std::string name, std::string reason, std::string expect, Edit change) {
    return {std::move(name), std::move(reason), std::move(expect), [change](const Workspace& w) {
                json d = w.doc();
                change(d);
                return w.write_gltf(d);
            }};
}

// A case that edits the document's text (what JSON cannot say, or too big for a DOM dump).
Case text(std::string name, std::string reason, std::string expect,
          std::function<std::string(std::string)> change) {
    return {std::move(name), std::move(reason), std::move(expect), [change](const Workspace& w) {
                return w.write("scene.gltf", change(w.doc().dump(1)));
            }};
}

std::string nested(size_t depth) {
    return std::string(depth, '[') + std::string(depth, ']');
}

// The `k`-th occurrence of `c` XOR 1 ('{'->'z', ':'->';', ','->'-', '"'->'#', ']'->'\').
std::function<std::string(std::string)> flip(char c, size_t k) {
    return [c, k](std::string s) {
        size_t at = 0;
        for (size_t seen = 0; seen <= k; ++seen) at = s.find(c, seen == 0 ? 0 : at + 1);
        s[at] = static_cast<char>(s[at] ^ 1);
        return s;
    };
}

json& prim(json& d) {
    return d["meshes"][0]["primitives"][0];
}

std::vector<Case> accessor_cases() {
    return {
        edit("accessor_count_huge", "2^40 elements: far past the buffer and any memory",
             "accessor 0", [](json& d) { d["accessors"][0]["count"] = uint64_t{1} << 40; }),
        edit("accessor_count_negative", "a count of -1 (tinygltf would wrap it)",
             "accessors[0].count", [](json& d) { d["accessors"][0]["count"] = -1; }),
        edit("accessor_count_past_view", "5 elements in a view that holds 4", "accessor 0",
             [](json& d) { d["accessors"][0]["count"] = 5; }),
        edit("accessor_count_zero", "an accessor of no elements", "accessor 0",
             [](json& d) { d["accessors"][0]["count"] = 0; }),
        edit("accessor_offset_huge", "byteOffset 2^62", "accessor 0",
             [](json& d) { d["accessors"][0]["byteOffset"] = uint64_t{1} << 62; }),
        edit("accessor_offset_negative", "byteOffset -4", "accessors[0].byteOffset",
             [](json& d) { d["accessors"][0]["byteOffset"] = -4; }),
        edit("accessor_offset_misaligned", "floats at byte offset 2 (glTF: a multiple of 4)",
             "accessor 0",
             [](json& d) {
                 d["bufferViews"][0]["byteLength"] = 52;  // room for 4 elements from byte 2
                 d["accessors"][0]["byteOffset"] = 2;
             }),
        edit("accessor_type_unknown", "type VEC7 does not exist", "accessors[0].type",
             [](json& d) { d["accessors"][0]["type"] = "VEC7"; }),
        edit("accessor_component_double", "componentType 5130 (double) is not glTF 2.0",
             "accessor 0", [](json& d) { d["accessors"][0]["componentType"] = 5130; }),
        edit("accessor_sparse_count_huge", "a sparse block of 2^30 substitutions", "accessor 0",
             [](json& d) {
                 d["accessors"][0]["sparse"] = {
                     {"count", uint64_t{1} << 30},
                     {"indices", {{"bufferView", 4}, {"componentType", 5125}}},
                     {"values", {{"bufferView", 0}}}};
             }),
        edit("stride_too_small", "byteStride 4 under a 12-byte element", "accessor 0",
             [](json& d) { d["bufferViews"][0]["byteStride"] = 4; }),
        edit("stride_misaligned", "byteStride 14 (glTF: a multiple of 4)",
             "bufferViews[0].byteStride", [](json& d) { d["bufferViews"][0]["byteStride"] = 14; }),
        edit("stride_too_large", "byteStride 256 (glTF: at most 252)", "bufferViews[0].byteStride",
             [](json& d) { d["bufferViews"][0]["byteStride"] = 256; }),
        edit("stride_negative", "byteStride -12", "bufferViews[0].byteStride",
             [](json& d) { d["bufferViews"][0]["byteStride"] = -12; }),
        edit("view_past_buffer", "a 100000-byte view in a 2376-byte buffer", "bufferView 0",
             [](json& d) { d["bufferViews"][0]["byteLength"] = 100000; }),
        edit("view_offset_huge", "view byteOffset 2^63", "bufferView 1",
             [](json& d) { d["bufferViews"][1]["byteOffset"] = uint64_t{1} << 63; }),
        edit("view_buffer_out_of_range", "a view of buffer 5 (there is one)", "bufferView 0",
             [](json& d) { d["bufferViews"][0]["buffer"] = 5; }),
        edit("buffer_length_mismatch", "byteLength 5000 for a 2376-byte file", "buffers[0].uri",
             [](json& d) { d["buffers"][0]["byteLength"] = 5000; }),
    };
}

std::vector<Case> index_cases() {
    return {
        edit("indices_accessor_out_of_range", "indices names accessor 999",
             "meshes[0].primitives[0].indices: accessor 999",
             [](json& d) { prim(d)["indices"] = 999; }),
        edit("position_accessor_out_of_range", "POSITION names accessor 999",
             "meshes[0].primitives[0].attributes.POSITION: accessor 999",
             [](json& d) { prim(d)["attributes"]["POSITION"] = 999; }),
        edit("material_out_of_range", "material 99 of 4", "material 99",
             [](json& d) { prim(d)["material"] = 99; }),
        edit("node_mesh_out_of_range", "node 1 places mesh 99", "node 1",
             [](json& d) { d["nodes"][1]["mesh"] = 99; }),
        edit("node_camera_out_of_range", "node 1 holds camera 5", "node 1",
             [](json& d) { d["nodes"][1]["camera"] = 5; }),
        edit("texture_source_out_of_range", "texture 0 shows image 99", "texture 0",
             [](json& d) { d["textures"][0]["source"] = 99; }),
        edit("texture_sampler_out_of_range", "texture 0 uses sampler 99", "texture 0",
             [](json& d) { d["textures"][0]["sampler"] = 99; }),
        edit("material_texture_out_of_range", "baseColorTexture index 50", "texture 50",
             [](json& d) {
                 d["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 50}};
             }),
        edit("scene_node_out_of_range", "scene 0 lists node 9999", "node 9999",
             [](json& d) { d["scenes"][0]["nodes"][0] = 9999; }),
        edit("scene_index_out_of_range", "scene 7 of 1", "scene 7",
             [](json& d) { d["scene"] = 7; }),
        edit("node_cycle", "node 1 is its own child", "node 1",
             [](json& d) { d["nodes"][1]["children"] = {1}; }),
        edit("node_two_parents", "node 1 is also a child of node 0", "node 1",
             [](json& d) { d["nodes"][0]["children"] = {1}; }),
    };
}

std::vector<Case> hierarchy_cases() {
    return {
        edit("node_chain_10000", "a 10,000-deep chain of nodes, a mesh at its end", "levels deep",
             [](json& d) {
                 const size_t first = d["nodes"].size();
                 for (size_t i = 0; i < 10000; ++i) {
                     json node = {{"name", "link"}};
                     if (i + 1 < 10000)
                         node["children"] = {first + i + 1};
                     else
                         node["mesh"] = 0;
                     d["nodes"].push_back(node);
                 }
                 d["scenes"][0]["nodes"].push_back(first);
             }),
        edit("nodes_100000", "100,000 nodes (1.8 GB before the limit)",
             "nodes has more than 65536 entries",
             [](json& d) {
                 for (int i = 0; i < 100000; ++i) d["nodes"].push_back({{"mesh", 0}});
             }),
        text("extras_nested_15000", "JSON nested 15,000 deep inside extras (tinygltf recursed)",
             "byte ",
             [](std::string s) { return "{\"extras\":" + nested(15000) + "," + s.substr(1); }),
        text("extension_nested_15000", "JSON nested 15,000 deep inside a node extension", "byte ",
             [](std::string s) {
                 const std::string key = "\"name\": \"backdrop\"";
                 const size_t at = s.find(key);
                 return s.substr(0, at) +
                        "\"extensions\": {\"EXT_deep\": {\"a\": " + nested(15000) + "}}, " +
                        s.substr(at);
             }),
        text("json_nested_65", "65 levels of arrays: one past the limit", "byte ",
             [](std::string s) { return "{\"extras\":" + nested(65) + "," + s.substr(1); }),
    };
}

std::vector<Case> number_cases() {
    return {
        text("matrix_overflow_literal", "a matrix entry 1e400 (no double holds it)", "byte ",
             [](std::string s) {
                 const size_t at = s.find("\"name\": \"ground\"");
                 return s.substr(0, at) + "\"matrix\": [1e400,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1], " +
                        s.substr(at);
             }),
        edit("translation_beyond_float", "translation 1e39 (no float holds it)", "node 0",
             [](json& d) {
                 d["nodes"][0]["translation"] = {1e39, 0, 0};
             }),
        edit("world_transform_overflow", "scales of 1e30 twice: the world matrix overflows",
             "not finite",
             [](json& d) {
                 d["nodes"][1]["scale"] = {1e30, 1e30, 1e30};
                 d["nodes"][1]["children"] = {d["nodes"].size()};
                 d["nodes"].push_back({{"mesh", 0}, {"scale", {1e30, 1e30, 1e30}}});
             }),
        edit("rotation_zero", "a zero quaternion has no rotation", "node 1",
             [](json& d) {
                 d["nodes"][1]["rotation"] = {0, 0, 0, 0};
             }),
        edit("camera_znear_zero", "znear 0: no perspective projection exists (glTF: > 0)",
             "camera 0", [](json& d) { d["cameras"][0]["perspective"]["znear"] = 0; }),
        edit("camera_yfov_zero", "yfov 0", "camera 0",
             [](json& d) { d["cameras"][0]["perspective"]["yfov"] = 0; }),
    };
}

std::vector<Case> document_cases() {
    std::vector<Case> cases = {
        edit("required_extension_unknown", "a required extension nobody implements",
             "EXT_unknown_feature",
             [](json& d) {
                 d["extensionsUsed"] = {"EXT_unknown_feature"};
                 d["extensionsRequired"] = {"EXT_unknown_feature"};
             }),
        edit("gltf_version_1", "glTF 1.0", "glTF 1.0",
             [](json& d) { d["asset"]["version"] = "1.0"; }),
        edit("no_asset", "asset is required", "not supported", [](json& d) { d.erase("asset"); }),
        text("top_level_array", "the top level is an array", "not a glTF file",
             [](std::string) { return std::string("[1, 2, 3]"); }),
        text("json_truncated_half", "the text cut in half", "invalid JSON",
             [](std::string s) { return s.substr(0, s.size() / 2); }),
        text("json_truncated_one_byte", "just '{'", "invalid JSON",
             [](std::string) { return std::string("{"); }),
        text("json_binary_garbage", "bytes that are not text", "invalid JSON",
             [](std::string) { return std::string("\x01\x02\xff\xfe{", 5); }),
    };
    const std::pair<char, size_t> flips[] = {{'{', 40},  {':', 100}, {',', 60},
                                             {'"', 301}, {']', 9},   {'}', 30}};
    for (const auto& [c, k] : flips) {
        cases.push_back(text("json_flip_" + std::to_string(int(c)) + "_" + std::to_string(k),
                             std::string("occurrence ") + std::to_string(k) + " of '" + c +
                                 "' with its low bit flipped",
                             "invalid JSON", flip(c, k)));
    }
    return cases;
}

std::vector<Case> uri_cases() {
    auto uri = [](std::string name, std::string reason, std::string expect, const char* array,
                  std::string value) {
        return edit(std::move(name), std::move(reason), std::move(expect),
                    [array, value](json& d) { d[array][0]["uri"] = value; });
    };
    auto special = [](std::string name, std::string reason, std::string expect, const char* array,
                      std::string file, std::function<void(const fs::path&)> make_file) {
        return Case{std::move(name), std::move(reason), std::move(expect),
                    [array, file, make_file](const Workspace& w) {
                        make_file(w.dir() / file);
                        json d = w.doc();
                        d[array][0]["uri"] = file;
                        return w.write_gltf(d);
                    }};
    };
    auto fifo = [](const fs::path& p) { ::mkfifo(p.c_str(), 0600); };
    auto dev_zero = [](const fs::path& p) { fs::create_symlink("/dev/zero", p); };
    auto dir = [](const fs::path& p) { fs::create_directory(p); };
    return {
        uri("buffer_uri_dot", "buffer uri \".\" (tinygltf: std::bad_alloc)", "is a directory",
            "buffers", "."),
        uri("image_uri_dot", "image uri \".\"", "is a directory", "images", "."),
        special("buffer_uri_directory", "the buffer is a folder", "buffers[0].uri", "buffers",
                "sub", dir),
        special("image_uri_directory", "the texture is a folder", "images[0].uri", "images", "tex",
                dir),
        special("buffer_uri_fifo", "a FIFO: reading it would block forever", "is a FIFO", "buffers",
                "pipe.bin", fifo),
        special("image_uri_fifo", "a FIFO as a texture", "is a FIFO", "images", "pipe.png", fifo),
        special("buffer_uri_dev_zero_link", "a link to /dev/zero: endless zeros",
                "character device", "buffers", "zero.bin", dev_zero),
        special("image_uri_dev_zero_link", "a texture linked to /dev/zero", "character device",
                "images", "zero.png", dev_zero),
        uri("buffer_uri_dev_zero", "buffer uri /dev/zero (was refused as File not found)",
            "character device", "buffers", "/dev/zero"),
        uri("buffer_uri_missing", "no such file", "buffers[0].uri", "buffers", "nothere.bin"),
        uri("image_uri_missing", "no such texture", "images[0].uri", "images", "nothere.png"),
        uri("buffer_uri_nul", "%00 decodes to a NUL byte in the path", "NUL", "buffers",
            "scene%00.bin"),
        uri("data_uri_bad_base64", "'@' is not base64", "buffers[0].uri", "buffers",
            "data:application/octet-stream;base64,@@@@"),
        uri("data_uri_unknown_type", "not a data: URI tinygltf reads", "buffers[0].uri", "buffers",
            "data:foo/bar,xyz"),
        uri("data_uri_short", "10 bytes for a 2376-byte buffer", "buffers[0].uri", "buffers",
            "data:application/octet-stream;base64,AAAAAAAAAAAAAA=="),
        uri("image_data_uri_text", "\"hello\" as a PNG", "images[0]", "images",
            "data:image/png;base64,aGVsbG8="),
    };
}

}  // namespace

std::vector<Case> json_cases() {
    std::vector<Case> cases;
    for (auto* family :
         {accessor_cases, index_cases, hierarchy_cases, number_cases, document_cases, uri_cases})
        for (Case& c : family()) cases.push_back(std::move(c));
    return cases;
}

}  // namespace ds::test::corpus
