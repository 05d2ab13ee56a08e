#pragma once
// Checks of PNG and JPEG bytes that run before stb_image 2.27 sees them, for the inputs it
// mishandles: a PNG's empty IDAT chunk (stb memcpys to null), a PNG without image data, a JPEG
// Huffman table of more than 256 codes (stb writes past its table). Used by the glTF importer
// (gltf_image.cpp) and by whatever else decodes a PNG it did not write (capture folders).
// Each throws InputError with a WHAT only; the caller names the file.
#include <cstdint>
#include <string>

namespace ds::scene {

uint32_t be32(const unsigned char* p);  // a big-endian 32-bit value
bool is_png(const unsigned char* bytes, int size);
bool is_jpeg(const unsigned char* bytes, int size);

// Walks a PNG's chunks; refuses a PNG with no IDAT bytes. When there are empty IDAT chunks,
// `cleaned` receives the file without them (decode that instead); otherwise it stays empty.
void check_png_chunks(const unsigned char* bytes, int size, std::string& cleaned);

// Walks a JPEG's marker segments and checks every Huffman table.
void check_jpeg_segments(const unsigned char* bytes, int size);

}  // namespace ds::scene
