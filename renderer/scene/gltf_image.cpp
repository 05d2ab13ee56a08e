#include "renderer/scene/gltf_image.h"

#include <algorithm>
#include <climits>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "renderer/scene/gltf_source.h"
#include "renderer/scene/image_checks.h"
#include "renderer/scene/import_limits.h"
#include "renderer/scene/import_util.h"

// Debian's stb_image (libstb), which decodes more than the two glTF formats: decode() takes
// PNG and JPEG only. stb's own cap on dimensions (2^24) stays above ours, so that stbi_info
// reports a large header and the message can say which limit it passes.
#include <stb/stb_image.h>

namespace ds::scene::detail {
namespace {

struct Freer {
    void operator()(void* p) const { stbi_image_free(p); }
};

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
    if (!is_png(bytes, size) && !is_jpeg(bytes, size))
        fail("not a PNG or JPEG image (neither signature)");
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
    std::string what = "images[" + std::to_string(index) + "]";
    if (!image->uri.empty()) what += " (" + quote_value(image->uri) + ")";
    try {
        const auto missing = budget.missing.find(decode_uri(image->uri));
        if (!image->uri.empty() && missing != budget.missing.end()) fail(missing->second);
        decode(*image, req_width, req_height, bytes, size, budget);
        return true;
    } catch (const InputError& e) {
        what += ": " + std::string(e.what());
        if (budget.lenient) {
            budget.problems[size_t(index)] = what;
            return true;  // no pixels: the importer drops its textures
        }
        if (budget.error.empty()) budget.error = what;
        if (err) *err += what;
        return false;
    }
}

}  // namespace ds::scene::detail
