#pragma once
// OpenEXR files of a capture's resources (resources/NAME.exr): raw values, float or u32
// channels named by meaning (resource_files.h decides the names), through OpenEXR, the
// industry's reference library. One part, scanlines, ZIP compression. Channels of one sample
// of a multisampled image share a layer prefix ("sample1.Z").
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ds::capture {

struct ExrChannel {
    std::string name;
    bool is_uint = false;         // UINT (counts, ids); else FLOAT
    std::vector<float> floats;    // width * height, row 0 = top (FLOAT channels)
    std::vector<uint32_t> uints;  // the same (UINT channels)
};

struct ExrImage {
    uint32_t width = 0, height = 0;
    std::vector<ExrChannel> channels;  // write: any order; read: OpenEXR's (sorted by name)

    const ExrChannel* find(std::string_view name) const;
};

// Encodes in memory and writes through write_new_file (every byte checked, nothing left on
// failure). Throws ds::Error "PATH: …" for a channel whose size is not width * height.
void write_exr(const std::filesystem::path& path, const ExrImage& image);

// Every channel of the file's first part: FLOAT and UINT as stored, HALF widened to float.
// Throws ds::Error "PATH: …" (missing, not an EXR, truncated, tiled or deep).
ExrImage read_exr(const std::filesystem::path& path);

}  // namespace ds::capture
