#include "renderer/scene/image_checks.h"

#include <algorithm>
#include <cstring>
#include <vector>

#include "renderer/scene/import_util.h"

namespace ds::scene {

using detail::fail;

uint32_t be32(const unsigned char* p) {
    return uint32_t{p[0]} << 24 | uint32_t{p[1]} << 16 | uint32_t{p[2]} << 8 | p[3];
}

bool is_png(const unsigned char* bytes, int size) {
    static const unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    return size >= 8 && std::memcmp(bytes, kPng, 8) == 0;
}

// A PNG's chunks, walked before stb sees them. stb copies each IDAT chunk into a buffer it
// allocates on the first non-empty one, so an empty IDAT before any data is a memcpy to null
// (undefined behaviour, found by UBSan). Empty IDAT chunks carry nothing: when there are any,
// `cleaned` receives the file without them. A PNG with no IDAT bytes at all is refused here; a
// chunk that runs past the end counts what is there and stb reports the truncation.
void check_png_chunks(const unsigned char* bytes, int size, std::string& cleaned) {
    const size_t total = size_t(size);
    uint64_t idat_bytes = 0;
    std::vector<size_t> empty_idats;  // where each empty IDAT chunk starts
    for (size_t pos = 8; pos + 12 <= total;) {
        const size_t len = be32(bytes + pos);
        const unsigned char* type = bytes + pos + 4;
        const size_t room = total - pos - 12;
        const bool idat = std::memcmp(type, "IDAT", 4) == 0;
        if (idat) idat_bytes += std::min(len, room);
        if (idat && len == 0) empty_idats.push_back(pos);
        if (len > room || std::memcmp(type, "IEND", 4) == 0) break;
        pos += 12 + len;
    }
    if (idat_bytes == 0) fail("PNG has no image data (no IDAT bytes)");
    const auto* chars = reinterpret_cast<const char*>(bytes);
    size_t from = 0;
    for (const size_t at : empty_idats) {
        cleaned.append(chars + from, at - from);
        from = at + 12;
    }
    if (!empty_idats.empty()) cleaned.append(chars + from, total - from);
}

bool is_jpeg(const unsigned char* bytes, int size) {
    return size >= 3 && bytes[0] == 0xff && bytes[1] == 0xd8 && bytes[2] == 0xff;
}

namespace {

// One DHT segment's tables (`data`, `length` bytes after the length field): each is a class/id
// byte, 16 code counts and as many symbols. stb_image 2.27 builds a table into 257 entries
// without checking the counts' sum (an out-of-bounds write for more than 256 codes, found by
// the fuzzer; stb 2.28 refuses it), so such a table is refused here.
void check_huffman_tables(const unsigned char* data, size_t length) {
    size_t at = 0;
    while (at < length) {
        if (length - at < 17) fail("JPEG Huffman table is cut short");
        size_t codes = 0;
        for (size_t i = 1; i <= 16; ++i) codes += data[at + i];
        if (codes > 256)
            fail("JPEG Huffman table declares " + std::to_string(codes) + " codes (at most 256)");
        at += 17 + codes;
    }
}

}  // namespace

// A JPEG's marker segments, walked before stb decodes: every DHT checked (above). Entropy-coded
// data after SOS is skipped to the next marker (0xFF followed by neither 0x00 nor RSTn), so the
// tables between a progressive JPEG's scans are checked too. Stops at EOI or the end.
void check_jpeg_segments(const unsigned char* bytes, int size) {
    const size_t total = size_t(size);
    size_t at = 2;
    while (at + 4 <= total) {
        if (bytes[at] != 0xff) {  // entropy-coded data: find the next marker
            ++at;
            continue;
        }
        const unsigned char marker = bytes[at + 1];
        if (marker == 0xff || marker == 0x00 || (marker >= 0xd0 && marker <= 0xd7)) {
            ++at;  // fill byte, stuffed 0xFF, restart marker
            continue;
        }
        if (marker == 0xd9) return;  // EOI
        const size_t length = size_t(bytes[at + 2]) << 8 | bytes[at + 3];
        if (length < 2 || at + 2 + length > total) return;  // stb reports the truncation
        if (marker == 0xc4) check_huffman_tables(bytes + at + 4, length - 2);
        at += 2 + length;
    }
}

}  // namespace ds::scene
