// Malformed corpus, part 2: the binary side (truncated .bin and .glb files, broken GLB
// headers, NaN/Inf and out-of-range values in the buffer, broken and oversized PNG textures)
// and scene paths that are not regular files.
#include <sys/stat.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

#include "malformed_corpus.h"

namespace ds::test::corpus {
namespace {

std::string u32(uint32_t v) {
    std::string out;
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>(v >> (8 * i)));
    return out;
}

std::string be32(uint32_t v) {
    std::string out;
    for (int i = 3; i >= 0; --i) out.push_back(static_cast<char>(v >> (8 * i)));
    return out;
}

uint32_t crc32(const std::string& bytes) {
    uint32_t crc = 0xffffffffu;
    for (unsigned char b : bytes) {
        crc ^= b;
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

std::string png_chunk(const std::string& type, const std::string& data) {
    return be32(static_cast<uint32_t>(data.size())) + type + data + be32(crc32(type + data));
}

// A PNG whose header declares width x height (RGBA8) followed by `idat` bytes of zeros as its
// image data: the header is all a decoder needs to decide how much to allocate.
std::string png_claiming(uint32_t width, uint32_t height, size_t idat) {
    const std::string ihdr = be32(width) + be32(height) + std::string("\x08\x06\x00\x00\x00", 5);
    return std::string("\x89PNG\r\n\x1a\n", 8) + png_chunk("IHDR", ihdr) +
           png_chunk("IDAT", std::string(idat, '\0')) + png_chunk("IEND", "");
}

// Writes scene.bin changed by `change`, keeps scene.gltf.
Case bin_edit(std::string name, std::string reason, std::string expect,
              std::function<void(const Workspace&, std::string&)> change) {
    return {std::move(name), std::move(reason), std::move(expect), [change](const Workspace& w) {
                std::string bin = w.bin();
                change(w, bin);
                w.write("scene.bin", bin);
                return w.dir() / "scene.gltf";
            }};
}

// scene.glb (the export as GLB) changed by `change`.
Case glb_edit(std::string name, std::string reason, std::string expect,
              std::function<void(std::string&)> change) {
    return {std::move(name), std::move(reason), std::move(expect), [change](const Workspace& w) {
                std::string glb = w.glb(w.doc(), w.bin());
                change(glb);
                return w.write("scene.glb", glb);
            }};
}

// Image 0's file replaced by `bytes`.
Case texture(std::string name, std::string reason, std::string bytes,
             std::string expect = "images[0]") {
    return {std::move(name), std::move(reason), std::move(expect), [bytes](const Workspace& w) {
                const json d = w.doc();
                w.write(d["images"][0]["uri"].get<std::string>(), bytes);
                return w.dir() / "scene.gltf";
            }};
}

void put_float(std::string& bin, size_t at, float v) {
    std::memcpy(bin.data() + at, &v, sizeof v);
}

std::vector<Case> truncation_cases() {
    std::vector<Case> cases;
    for (const char* which : {"0", "1", "half", "minus1"}) {
        cases.push_back(bin_edit(std::string("bin_truncated_") + which,
                                 "the .bin cut short: the buffer's bytes are missing",
                                 "buffers[0].uri", [which](const Workspace&, std::string& bin) {
                                     const std::string w = which;
                                     const size_t n = w == "0"      ? 0
                                                      : w == "1"    ? 1
                                                      : w == "half" ? bin.size() / 2
                                                                    : bin.size() - 1;
                                     bin.resize(n);
                                 }));
    }
    for (size_t length : {4, 8, 11, 12, 16, 19, 20, 27, 100, 1000}) {
        cases.push_back(glb_edit("glb_truncated_" + std::to_string(length),
                                 "a GLB cut after " + std::to_string(length) + " bytes", "GLB",
                                 [length](std::string& glb) { glb.resize(length); }));
    }
    cases.push_back(glb_edit("glb_truncated_minus1", "a GLB missing its last byte", "",
                             [](std::string& glb) { glb.pop_back(); }));
    cases.push_back(glb_edit("glb_truncated_half", "a GLB cut in the BIN chunk", "",
                             [](std::string& glb) { glb.resize(glb.size() - 1000); }));
    return cases;
}

std::vector<Case> glb_header_cases() {
    return {
        glb_edit("glb_version_3", "container version 3", "version 3",
                 [](std::string& g) { g.replace(4, 4, u32(3)); }),
        glb_edit("glb_json_chunk_type", "first chunk type JSOX", "not JSON",
                 [](std::string& g) { g[19] = 'X'; }),
        glb_edit("glb_json_length_huge", "JSON chunk length 2^31", "past the end",
                 [](std::string& g) { g.replace(12, 4, u32(0x80000000u)); }),
        glb_edit("glb_bin_length_huge", "BIN chunk length 2^31", "",
                 [](std::string& g) {
                     const uint32_t json_length = static_cast<uint8_t>(g[12]) |
                                                  static_cast<uint8_t>(g[13]) << 8 |
                                                  static_cast<uint8_t>(g[14]) << 16;
                     g.replace(20 + json_length, 4, u32(0x80000000u));
                 }),
        glb_edit("glb_total_length_small", "header length 24", "",
                 [](std::string& g) { g.replace(8, 4, u32(24)); }),
        glb_edit("glb_json_byte_flip", "a brace in the JSON chunk flipped", "invalid JSON",
                 [](std::string& g) { g[20] = static_cast<char>(g[20] ^ 1); }),
    };
}

std::vector<Case> value_cases() {
    return {
        bin_edit("bin_nan_position", "a NaN x coordinate", "POSITION",
                 [](const Workspace& w, std::string& bin) {
                     put_float(bin, w.accessor_offset(w.doc(), 0), std::nanf(""));
                 }),
        bin_edit("bin_inf_position", "an infinite y coordinate", "POSITION",
                 [](const Workspace& w, std::string& bin) {
                     put_float(bin, w.accessor_offset(w.doc(), 0) + 4, INFINITY);
                 }),
        bin_edit("bin_index_out_of_range", "index 0xffffffff in a 4-vertex mesh", "out of range",
                 [](const Workspace& w, std::string& bin) {
                     bin.replace(w.accessor_offset(w.doc(), 4), 4, u32(0xffffffffu));
                 }),
        bin_edit("bin_bytes_flipped_indices", "every index byte inverted", "out of range",
                 [](const Workspace& w, std::string& bin) {
                     const size_t at = w.accessor_offset(w.doc(), 4);
                     for (size_t i = at; i < at + 24; ++i) bin[i] = static_cast<char>(~bin[i]);
                 }),
    };
}

std::vector<Case> texture_cases() {
    return {
        texture("png_empty", "a 0-byte texture file", "", "images[0].uri"),
        texture("png_text", "a text file named .png", "this is not an image\n"),
        texture("png_claims_100000", "a PNG header claiming 100000 x 100000",
                png_claiming(100000, 100000, 64)),
        texture("png_claims_16384_zeros", "16384 x 16384 with 1 MB of zeros (decoded to 4.2 GB)",
                png_claiming(16384, 16384, 1 << 20)),
        texture("png_claims_8193", "8193 x 8193: each side allowed, the texel count not",
                png_claiming(8193, 8193, 64)),
        texture("png_claims_0", "a PNG 0 pixels wide", png_claiming(0, 16, 64)),
        texture("png_no_data", "a valid header and no image data", png_claiming(64, 64, 0)),
        {"png_truncated", "a real texture cut in half", "images[0]",
         [](const Workspace& w) {
             const std::string name = w.doc()["images"][0]["uri"].get<std::string>();
             std::ifstream in(w.dir() / name, std::ios::binary);
             std::string bytes((std::istreambuf_iterator<char>(in)), {});
             w.write(name, bytes.substr(0, bytes.size() / 2));
             return w.dir() / "scene.gltf";
         }},
        {"glb_embedded_png_claims_100000", "an image in the BIN chunk claiming 100000 x 100000",
         "images[0]",
         [](const Workspace& w) {
             json d = w.doc();
             std::string bin = w.bin();
             const std::string png = png_claiming(100000, 100000, 64);
             d["bufferViews"].push_back(
                 {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", png.size()}});
             bin += png;
             d["buffers"][0]["byteLength"] = bin.size();
             d["images"][0] = {{"bufferView", d["bufferViews"].size() - 1},
                               {"mimeType", "image/png"}};
             return w.write("scene.glb", w.glb(d, bin));
         }},
        {"image_view_past_buffer", "an image's buffer view ends past the buffer",
         "images[0].bufferView",
         [](const Workspace& w) {
             json d = w.doc();
             d["bufferViews"].push_back(
                 {{"buffer", 0}, {"byteOffset", 2000}, {"byteLength", 1000}});
             d["images"][0] = {{"bufferView", d["bufferViews"].size() - 1},
                               {"mimeType", "image/png"}};
             return w.write_gltf(d);
         }},
    };
}

std::vector<Case> scene_path_cases() {
    return {
        {"scene_is_directory", "the scene path is a folder", "is a directory",
         [](const Workspace& w) { return w.dir(); }},
        {"scene_is_fifo", "the scene path is a FIFO: opening it would block forever", "is a FIFO",
         [](const Workspace& w) {
             const fs::path p = w.dir() / "pipe.gltf";
             ::mkfifo(p.c_str(), 0600);
             return p;
         }},
        {"scene_is_dev_zero_link", "the scene is a link to /dev/zero", "character device",
         [](const Workspace& w) {
             const fs::path p = w.dir() / "zero.glb";
             fs::create_symlink("/dev/zero", p);
             return p;
         }},
        {"scene_empty", "an empty file", "empty file",
         [](const Workspace& w) { return w.write("empty.gltf", ""); }},
    };
}

}  // namespace

std::vector<Case> binary_cases() {
    std::vector<Case> cases;
    for (auto* family :
         {truncation_cases, glb_header_cases, value_cases, texture_cases, scene_path_cases})
        for (Case& c : family()) cases.push_back(std::move(c));
    return cases;
}

}  // namespace ds::test::corpus
