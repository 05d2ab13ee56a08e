#include "capture/image_writer.h"

#include <string>

#include "capture/file_output.h"
#include "renderer/common/error.h"
#include "renderer/common/quoted.h"

#include <stb/stb_image_write.h>  // Debian's libstb

namespace ds::capture {

std::string encode_png_rgba8(const std::filesystem::path& path, uint32_t width, uint32_t height,
                             const std::vector<uint8_t>& rgba8) {
    if (width == 0 || height == 0 || rgba8.size() != size_t(width) * height * 4) {
        throw Error(escaped(path.string()) + ": image size does not match its pixels");
    }
    std::string png;
    const auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), size_t(size));
    };
    const int stride = int(width * 4);
    // stb's default level (8) searches hard for little gain; 4 writes a 2048² map about twice
    // as fast for files a few percent larger.
    stbi_write_png_compression_level = 4;
    if (!stbi_write_png_to_func(append, &png, int(width), int(height), 4, rgba8.data(), stride)) {
        throw Error(escaped(path.string()) + ": cannot encode PNG");
    }
    return png;
}

void write_png_rgba8(const std::filesystem::path& path, uint32_t width, uint32_t height,
                     const std::vector<uint8_t>& rgba8) {
    // Encoded in memory, then written through write_new_file: stb's own file writer does not
    // check fwrite, so a short write (a full disk, a file-size limit) would go unnoticed.
    write_new_file(path, encode_png_rgba8(path, width, height, rgba8));
}

}  // namespace ds::capture
