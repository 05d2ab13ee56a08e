// Image files stb_image mishandles, checked before it reads them (renderer/scene/gltf_image.cpp):
// a PNG's empty IDAT chunk is dropped (stb would memcpy to null), a PNG with no image data at
// all is refused with one line, and so is a JPEG Huffman table of more than 256 codes (stb 2.27
// writes past its table).
#include <array>
#include <cstdint>
#include <string>

#include <gtest/gtest.h>

#include "renderer/common/error.h"
#include "renderer/scene/importer.h"

namespace ds::scene {
namespace {

std::string be32(uint32_t v) {
    return {char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
}

uint32_t crc32(const std::string& bytes) {
    uint32_t crc = 0xffffffffu;
    for (const unsigned char b : bytes) {
        crc ^= b;
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

std::string chunk(const std::string& type, const std::string& data) {
    return be32(uint32_t(data.size())) + type + data + be32(crc32(type + data));
}

// One RGBA8 pixel as a stored (uncompressed) zlib stream: filter byte 0, then the pixel.
std::string idat_for(const std::array<uint8_t, 4>& rgba) {
    const std::string raw = {'\0', char(rgba[0]), char(rgba[1]), char(rgba[2]), char(rgba[3])};
    uint32_t a = 1, b = 0;
    for (const unsigned char c : raw) {
        a = (a + c) % 65521;
        b = (b + a) % 65521;
    }
    return std::string("\x78\x01\x01\x05\x00\xfa\xff", 7) + raw + be32(b << 16 | a);
}

std::string png(const std::string& idat_chunks) {
    const std::string ihdr = be32(1) + be32(1) + std::string("\x08\x06\x00\x00\x00", 5);
    return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) + idat_chunks +
           chunk("IEND", "");
}

// A one-triangle scene whose material samples a.png.
const std::string kDocument = R"({
  "asset": {"version": "2.0"},
  "buffers": [{"uri": "a.bin", "byteLength": 60}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                  {"buffer": 0, "byteOffset": 36, "byteLength": 24}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
     "min": [0, 0, 0], "max": [1, 1, 0]},
    {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2"}],
  "images": [{"uri": "a.png"}],
  "textures": [{"source": 0}],
  "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "material": 0}]}],
  "nodes": [{"mesh": 0}],
  "scenes": [{"nodes": [0]}]
})";

std::string buffer() {
    const float data[15] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1};
    return std::string(reinterpret_cast<const char*>(data), sizeof data);
}

TEST(PngChunks, EmptyIdatChunksAreDroppedBeforeDecoding) {
    const std::string file =
        png(chunk("IDAT", "") + chunk("IDAT", idat_for({10, 20, 30, 40})) + chunk("IDAT", ""));
    const Scene s = load_gltf_memory(kDocument, {{"a.bin", buffer()}, {"a.png", file}}, "m.gltf");
    ASSERT_EQ(s.images.size(), 1u);
    EXPECT_EQ(s.images[0].rgba8, (std::vector<uint8_t>{10, 20, 30, 40}));
}

TEST(PngChunks, NoImageDataIsRefusedWithOneLine) {
    for (const std::string& idats :
         {std::string(), chunk("IDAT", ""), chunk("IDAT", "") + chunk("IDAT", "")}) {
        try {
            load_gltf_memory(kDocument, {{"a.bin", buffer()}, {"a.png", png(idats)}}, "m.gltf",
                             {.strict = true});
            FAIL() << "loaded";
        } catch (const InputError& e) {
            EXPECT_STREQ(e.what(),
                         "m.gltf: images[0] (\"a.png\"): PNG has no image data (no IDAT bytes)");
        }
    }
}

TEST(JpegSegments, AHuffmanTableOfMoreThan256CodesIsRefused) {
    std::string dht(1, '\0');                 // class 0, id 0
    dht += std::string(15, char(20)) + '\0';  // 15 lengths with 20 codes each: 300
    dht += std::string(300, '\x01');
    const std::string length = {char((dht.size() + 2) >> 8), char((dht.size() + 2) & 0xff)};
    const std::string jpeg = std::string("\xff\xd8\xff\xc4", 4) + length + dht + "\xff\xd9";
    try {
        load_gltf_memory(kDocument, {{"a.bin", buffer()}, {"a.png", jpeg}}, "m.gltf",
                         {.strict = true});
        FAIL() << "loaded";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(),
                     "m.gltf: images[0] (\"a.png\"): JPEG Huffman table declares 300 "
                     "codes (at most 256)");
    }
    // Lenient (the default), the same text is a warning and the texture is dropped.
    const Scene s = load_gltf_memory(kDocument, {{"a.bin", buffer()}, {"a.png", jpeg}}, "m.gltf");
    ASSERT_FALSE(s.warnings.empty());
    EXPECT_EQ(s.warnings[0].rfind("images[0] (\"a.png\"): JPEG Huffman table declares 300", 0), 0u)
        << s.warnings[0];
    for (const Material& m : s.materials) EXPECT_FALSE(m.base_color.present());
}

}  // namespace
}  // namespace ds::scene
