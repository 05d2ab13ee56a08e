// Malformed corpus, part 3: compressed files (issue 27). The meshopt and Draco atriums of
// tests/data/compressed/ without their textures (so that the decoder is what refuses them),
// each broken in one way: truncated and corrupted streams, counts, strides, modes and filters
// out of range, attributes the stream does not hold. Debian's meshoptimizer keeps its asserts
// and libdraco is not built with sanitizers: the importer's checks must stop each one first.
#include <fstream>
#include <iterator>

#include "malformed_corpus.h"

namespace ds::test::corpus {
namespace {

const fs::path kCompressed = fs::path(DS_SOURCE_DIR) / "tests/data/compressed";

std::string read_bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// `stem`.gltf without images (materials keep their factors) and its .bin, both changed.
Case compressed(std::string name, std::string reason, std::string expect, std::string stem,
                std::function<void(json&, std::string&)> change) {
    return {std::move(name), std::move(reason), std::move(expect),
            [stem, change](const Workspace& w) {
                json doc = json::parse(read_bytes(kCompressed / (stem + ".gltf")));
                std::string bin = read_bytes(kCompressed / (stem + ".bin"));
                doc.erase("images");
                doc.erase("textures");
                doc.erase("samplers");
                for (json& m : doc["materials"]) {
                    m.erase("normalTexture");
                    if (m.contains("pbrMetallicRoughness"))
                        m["pbrMetallicRoughness"].erase("baseColorTexture");
                }
                change(doc, bin);
                w.write(stem + ".bin", bin);
                return w.write_gltf(doc, "compressed.gltf");
            }};
}

// The first bufferView compressed in `mode` (meshopt).
json& meshopt_view(json& doc, const std::string& mode) {
    for (json& view : doc["bufferViews"])
        if (view.contains("extensions") &&
            view["extensions"]["EXT_meshopt_compression"]["mode"] == mode)
            return view["extensions"]["EXT_meshopt_compression"];
    throw std::runtime_error("no meshopt view in mode " + mode);
}

json& draco_of_first_primitive(json& doc) {
    return doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"];
}

std::vector<Case> meshopt_cases() {
    const std::string ext = "EXT_meshopt_compression";
    auto edit = [&](std::string name, std::string reason, std::string expect,
                    std::function<void(json&, std::string&)> change) {
        return compressed(std::move(name), std::move(reason), std::move(expect), "lossless_c",
                          std::move(change));
    };
    return {
        edit("meshopt_truncated_stream", "a vertex stream cut to 10 bytes", "does not decode",
             [](json& d, std::string&) { meshopt_view(d, "ATTRIBUTES")["byteLength"] = 10; }),
        edit("meshopt_corrupt_stream", "a vertex stream's bytes overwritten", ext,
             [](json& d, std::string& bin) {
                 const json& v = meshopt_view(d, "ATTRIBUTES");
                 const size_t at = v.value("byteOffset", size_t{0});
                 for (size_t i = 1; i < v["byteLength"].get<size_t>(); ++i) bin[at + i] = '\xff';
             }),
        edit("meshopt_codec_version_1", "a vertex stream of codec version 1 (meshopt 0.23+)",
             "does not decode",
             [](json& d, std::string& bin) {
                 bin[meshopt_view(d, "ATTRIBUTES").value("byteOffset", size_t{0})] = '\xa1';
             }),
        edit("meshopt_count_mismatch", "count × byteStride is not the view's byteLength",
             "byteLength",
             [](json& d, std::string&) {
                 json& v = meshopt_view(d, "ATTRIBUTES");
                 v["count"] = v["count"].get<uint64_t>() + 1;
             }),
        edit("meshopt_stride_6", "ATTRIBUTES with a byteStride that is no multiple of 4",
             "byteStride",
             [](json& d, std::string&) { meshopt_view(d, "ATTRIBUTES")["byteStride"] = 6; }),
        edit("meshopt_stride_512", "ATTRIBUTES with a byteStride over 256", "byteStride",
             [](json& d, std::string&) { meshopt_view(d, "ATTRIBUTES")["byteStride"] = 512; }),
        edit("meshopt_triangles_count", "TRIANGLES with a count that is no multiple of 3",
             "multiple of 3",
             [](json& d, std::string&) {
                 json& v = meshopt_view(d, "TRIANGLES");
                 v["count"] = v["count"].get<uint64_t>() - 1;
             }),
        edit("meshopt_index_stride_3", "TRIANGLES with a byteStride of 3", "byteStride",
             [](json& d, std::string&) { meshopt_view(d, "TRIANGLES")["byteStride"] = 3; }),
        edit("meshopt_filter_on_indices", "a filter on a TRIANGLES view", "needs mode ATTRIBUTES",
             [](json& d, std::string&) { meshopt_view(d, "TRIANGLES")["filter"] = "OCTAHEDRAL"; }),
        edit("meshopt_unknown_mode", "mode POINTS", "unknown mode",
             [](json& d, std::string&) { meshopt_view(d, "TRIANGLES")["mode"] = "POINTS"; }),
        edit("meshopt_unknown_filter", "filter SPHERICAL", "unknown filter",
             [](json& d, std::string&) { meshopt_view(d, "ATTRIBUTES")["filter"] = "SPHERICAL"; }),
        edit("meshopt_source_outside", "the stream's bytes lie past its buffer", "outside buffer",
             [](json& d, std::string&) {
                 meshopt_view(d, "ATTRIBUTES")["byteOffset"] = uint64_t{1} << 29;
             }),
        edit("meshopt_source_buffer_missing", "the stream's buffer index is out of range",
             "out of range",
             [](json& d, std::string&) { meshopt_view(d, "ATTRIBUTES")["buffer"] = 99; }),
    };
}

std::vector<Case> draco_cases() {
    const std::string ext = "KHR_draco_mesh_compression";
    auto edit = [&](std::string name, std::string reason, std::string expect,
                    std::function<void(json&, std::string&)> change) {
        return compressed(std::move(name), std::move(reason), std::move(expect), "draco_raw",
                          std::move(change));
    };
    auto view_of = [](json& d) -> json& {
        return d["bufferViews"][draco_of_first_primitive(d)["bufferView"].get<size_t>()];
    };
    return {
        edit("draco_truncated_stream", "a Draco stream cut in half", ext,
             [view_of](json& d, std::string&) {
                 json& v = view_of(d);
                 v["byteLength"] = v["byteLength"].get<uint64_t>() / 2;
             }),
        edit("draco_corrupt_stream", "a Draco stream's bytes overwritten after its header", ext,
             [view_of](json& d, std::string& bin) {
                 const json& v = view_of(d);
                 const size_t at = v.value("byteOffset", size_t{0});
                 for (size_t i = 16; i < v["byteLength"].get<size_t>(); ++i) bin[at + i] = '\x5a';
             }),
        edit("draco_not_draco", "the stream's bytes are not Draco at all", "not a Draco",
             [view_of](json& d, std::string& bin) {
                 const json& v = view_of(d);
                 const size_t at = v.value("byteOffset", size_t{0});
                 for (size_t i = 0; i < v["byteLength"].get<size_t>(); ++i) bin[at + i] = '\0';
             }),
        edit("draco_count_mismatch", "POSITION's count is not the stream's point count", "points",
             [](json& d, std::string&) {
                 const size_t a = d["meshes"][0]["primitives"][0]["attributes"]["POSITION"];
                 d["accessors"][a]["count"] = d["accessors"][a]["count"].get<uint64_t>() + 1;
             }),
        edit("draco_unknown_attribute", "POSITION names an attribute id the stream lacks",
             "no attribute",
             [](json& d, std::string&) {
                 draco_of_first_primitive(d)["attributes"]["POSITION"] = 99;
             }),
        edit("draco_view_outside", "the stream's bufferView lies past its buffer", "outside",
             [view_of](json& d, std::string&) { view_of(d)["byteOffset"] = uint64_t{1} << 29; }),
        edit("draco_huge_count", "POSITION claims 2^30 points", "out of range",
             [](json& d, std::string&) {
                 const size_t a = d["meshes"][0]["primitives"][0]["attributes"]["POSITION"];
                 d["accessors"][a]["count"] = uint64_t{1} << 30;
             }),
    };
}

}  // namespace

std::vector<Case> compressed_cases() {
    std::vector<Case> cases = meshopt_cases();
    for (Case& c : draco_cases()) cases.push_back(std::move(c));
    return cases;
}

}  // namespace ds::test::corpus
