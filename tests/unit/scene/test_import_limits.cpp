// The stated limits of import_limits.h, each just inside and just past its bound, through
// load_gltf_memory (no disk): the byte scan's depth and array counts, the hierarchy depth and
// the image header check.
#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include "renderer/common/error.h"
#include "renderer/scene/import_limits.h"
#include "renderer/scene/importer.h"

namespace ds::scene {
namespace {

std::string base64(const std::string& bytes) {
    static const char* kAlphabet =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    const size_t n = bytes.size();
    for (size_t i = 0; i < n; i += 3) {
        uint32_t v = uint32_t(uint8_t(bytes[i])) << 16;
        if (i + 1 < n) v |= uint32_t(uint8_t(bytes[i + 1])) << 8;
        if (i + 2 < n) v |= uint8_t(bytes[i + 2]);
        out += kAlphabet[(v >> 18) & 63];
        out += kAlphabet[(v >> 12) & 63];
        out += i + 1 < n ? kAlphabet[(v >> 6) & 63] : '=';
        out += i + 2 < n ? kAlphabet[v & 63] : '=';
    }
    return out;
}

// One triangle in a data: URI; `extra` goes into the top-level object, `nodes` after node 0.
std::string triangle(const std::string& extra = "", const std::string& nodes = "",
                     const std::string& scene_nodes = "0") {
    const float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    std::string bytes(sizeof p, '\0');
    std::memcpy(bytes.data(), p, sizeof p);
    return "{" + extra + R"("asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[)" +
           scene_nodes + R"(]}],"nodes":[{"mesh":0})" + nodes +
           R"(],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
           R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
           R"("min":[0,0,0],"max":[1,1,0]}],"bufferViews":[{"buffer":0,"byteLength":36}],)"
           R"("buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,)" +
           base64(bytes) + "\"}]}";
}

std::string doc_load_error(const std::string& doc) {
    try {
        load_gltf_memory(doc, {}, "mem.gltf", {.strict = true});
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

std::string nested(int depth) {
    return std::string(size_t(depth), '[') + std::string(size_t(depth), ']');
}

TEST(ImportLimits, TriangleLoads) {
    EXPECT_EQ(doc_load_error(triangle()), "");
}

TEST(ImportLimits, JsonDepthCountsEveryLevelAndNamesTheByte) {
    // The top-level object is level 1: 63 more levels are allowed, the 64th array is level 65.
    EXPECT_EQ(doc_load_error(triangle("\"extras\":" + nested(limits::kMaxJsonDepth - 1) + ",")),
              "");
    EXPECT_EQ(doc_load_error(triangle("\"extras\":" + nested(limits::kMaxJsonDepth) + ",")),
              "mem.gltf: byte 73: JSON nested more than 64 levels deep (the limit)");
    // Inside an extension too, and strings (with escaped quotes) do not count.
    EXPECT_NE(doc_load_error(triangle("\"extensions\":{\"EXT_x\":" + nested(15000) + "},"))
                  .find("levels deep"),
              std::string::npos);
    EXPECT_EQ(doc_load_error(triangle("\"extras\":\"\\\"" + std::string(500, '[') + "\",")), "");
}

TEST(ImportLimits, NodeCount) {
    std::string inside;
    for (size_t i = 1; i < limits::kMaxNodes; ++i) inside += ",{}";
    EXPECT_EQ(doc_load_error(triangle("", inside)), "");
    const std::string message = doc_load_error(triangle("", inside + ",{}"));
    EXPECT_EQ(message.rfind("mem.gltf: byte ", 0), 0u) << message;
    EXPECT_NE(message.find("nodes has more than 65536 entries (the limit)"), std::string::npos)
        << message;
}

TEST(ImportLimits, HierarchyDepth) {
    // Node 0 (the mesh) under a chain of `links` nodes: depth links + 1.
    auto chain = [](size_t links) {
        std::string nodes;
        for (size_t i = 1; i <= links; ++i)
            nodes += ",{\"children\":[" + std::to_string(i == 1 ? 0 : i - 1) + "]}";
        return triangle("", nodes, std::to_string(links));
    };
    EXPECT_EQ(doc_load_error(chain(limits::kMaxHierarchyDepth - 1)), "");
    EXPECT_EQ(doc_load_error(chain(limits::kMaxHierarchyDepth)),
              "mem.gltf: node 0: the node hierarchy is more than 1024 levels deep (the limit)");
}

// The header is read first: a PNG claiming 100000 x 100000 is refused without decoding.
TEST(ImportLimits, ImageDimensionsFromTheHeader) {
    auto be32 = [](uint32_t v) {
        return std::string{char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
    };
    const std::string png = std::string("\x89PNG\r\n\x1a\n", 8) + be32(13) + "IHDR" + be32(100000) +
                            be32(100000) + std::string("\x08\x06\0\0\0", 5) + be32(0);
    const std::string images =
        R"("images":[{"uri":"data:image/png;base64,)" + base64(png) + "\"}],";
    EXPECT_EQ(doc_load_error(triangle(images)),
              "mem.gltf: images[0]: image is 100000x100000, beyond the limit of 16384 per side "
              "and 67108864 texels");
}

}  // namespace
}  // namespace ds::scene
