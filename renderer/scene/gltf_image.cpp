#include "renderer/scene/gltf_image.h"

#include <algorithm>
#include <climits>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "renderer/scene/import_limits.h"
#include "renderer/scene/import_util.h"

// A private copy of stb_image (static functions) for the two glTF formats. Other libraries in
// the process may carry their own stb_image; static linkage keeps them apart. stb's own cap on
// dimensions (2^24) stays above ours, so that stbi_info reports a large header and the message
// can say which limit it passes.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_NO_STDIO
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

namespace ds::scene::detail {
namespace {

struct Freer {
    void operator()(void* p) const { stbi_image_free(p); }
};

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

// Width and height from the header. A PNG's are read here directly: stbi_info refuses a PNG
// whose decoded size passes 1 GiB with a reason that names no size.
bool read_header(const unsigned char* bytes, int size, int& w, int& h) {
    if (size >= 24 && is_png(bytes, size) && std::memcmp(bytes + 12, "IHDR", 4) == 0) {
        const uint32_t width = be32(bytes + 16);
        const uint32_t height = be32(bytes + 20);
        w = int(std::min<uint32_t>(width, INT32_MAX));
        h = int(std::min<uint32_t>(height, INT32_MAX));
        return true;
    }
    int comp = 0;
    return stbi_info_from_memory(bytes, size, &w, &h, &comp) != 0;
}

void decode(tinygltf::Image& image, int req_width, int req_height, const unsigned char* bytes,
            int size, ImageBudget& budget) {
    if (size <= 0) fail("empty image");
    // Before stb reads the header: stbi_info already builds the tables it meets before SOF.
    if (is_jpeg(bytes, size)) check_jpeg_segments(bytes, size);
    int w = 0;
    int h = 0;
    if (!read_header(bytes, size, w, h))
        fail(std::string("not a PNG or JPEG image (") + stbi_failure_reason() + ")");
    const uint64_t texels = uint64_t(std::max(w, 0)) * uint64_t(std::max(h, 0));
    if (w < 1 || h < 1) fail("image is " + std::to_string(w) + "x" + std::to_string(h));
    if (w > limits::kMaxImageSide || h > limits::kMaxImageSide || texels > limits::kMaxImageTexels)
        fail("image is " + std::to_string(w) + "x" + std::to_string(h) + ", beyond the limit of " +
             std::to_string(limits::kMaxImageSide) + " per side and " +
             std::to_string(limits::kMaxImageTexels) + " texels");
    const bool wide = stbi_is_16_bit_from_memory(bytes, size) != 0;
    const uint64_t bytes_needed = texels * 4 * (wide ? 2 : 1);
    if (bytes_needed > limits::kMaxTotalImageBytes - budget.decoded_bytes)
        fail("decoding it would take the scene's images past the limit of " +
             std::to_string(limits::kMaxTotalImageBytes) + " bytes");
    if ((req_width > 0 && req_width != w) || (req_height > 0 && req_height != h))
        fail("image is " + std::to_string(w) + "x" + std::to_string(h) + " but declares " +
             std::to_string(req_width) + "x" + std::to_string(req_height));

    std::string cleaned;
    if (is_png(bytes, size)) check_png_chunks(bytes, size, cleaned);
    if (!cleaned.empty()) {
        bytes = reinterpret_cast<const unsigned char*>(cleaned.data());
        size = int(cleaned.size());
    }
    int dw = 0;
    int dh = 0;
    int comp = 0;
    std::unique_ptr<unsigned char, Freer> pixels(
        wide ? reinterpret_cast<unsigned char*>(
                   stbi_load_16_from_memory(bytes, size, &dw, &dh, &comp, 4))
             : stbi_load_from_memory(bytes, size, &dw, &dh, &comp, 4));
    if (!pixels) fail(std::string("cannot decode the image (") + stbi_failure_reason() + ")");
    if (dw != w || dh != h) fail("image size changed while decoding");
    image.width = w;
    image.height = h;
    image.component = 4;
    image.bits = wide ? 16 : 8;
    image.pixel_type =
        wide ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT : TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image.image.assign(pixels.get(), pixels.get() + bytes_needed);
    budget.decoded_bytes += bytes_needed;
}

}  // namespace

bool load_image_checked(tinygltf::Image* image, int index, std::string* err, std::string*,
                        int req_width, int req_height, const unsigned char* bytes, int size,
                        void* user) {
    auto& budget = *static_cast<ImageBudget*>(user);
    try {
        decode(*image, req_width, req_height, bytes, size, budget);
        return true;
    } catch (const InputError& e) {
        std::string what = "images[" + std::to_string(index) + "]";
        if (!image->uri.empty()) what += " (" + quote_value(image->uri) + ")";
        what += ": " + std::string(e.what());
        if (budget.error.empty()) budget.error = what;
        if (err) *err += what;
        return false;
    }
}

}  // namespace ds::scene::detail
