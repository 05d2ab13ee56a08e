#include "renderer/capture/image_writer.h"

#include <string>

#include "renderer/common/error.h"

// Static, so another library in the process may carry its own copy of stb_image_write.
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

namespace ds::capture {

void write_png_rgba8(const std::filesystem::path& path, uint32_t width, uint32_t height,
                     const std::vector<uint8_t>& rgba8) {
    if (width == 0 || height == 0 || rgba8.size() != size_t(width) * height * 4) {
        throw Error(path.string() + ": image size does not match its pixels");
    }
    const int stride = int(width * 4);
    if (!stbi_write_png(path.c_str(), int(width), int(height), 4, rgba8.data(), stride)) {
        throw Error(path.string() + ": cannot write PNG");
    }
}

}  // namespace ds::capture
