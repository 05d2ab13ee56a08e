#pragma once
// Image files written by captures.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace ds::capture {

// 8-bit RGBA, tightly packed, top row first. Throws ds::Error when the file cannot be written.
void write_png_rgba8(const std::filesystem::path& path, uint32_t width, uint32_t height,
                     const std::vector<uint8_t>& rgba8);

// The PNG file's bytes, for a writer of its own (the plot writer's write_file_atomically).
// `path` names the file in the errors thrown (ds::Error).
std::string encode_png_rgba8(const std::filesystem::path& path, uint32_t width, uint32_t height,
                             const std::vector<uint8_t>& rgba8);

}  // namespace ds::capture
