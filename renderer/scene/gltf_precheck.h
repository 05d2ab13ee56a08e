#pragma once
// Checks of a glTF file's raw JSON, made before tinygltf parses it. tinygltf silently drops
// values of the wrong type (a `"name": 42`, an array where an object belongs, an index of -1)
// and reads glTF 1.0 files as empty 2.0 models; these checks turn both into clear errors.
// Internal to renderer/scene; errors are InputError with a WHAT only.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ds::scene::detail {

// A buffer or image that names a file (not a data: URI).
struct FileRef {
    std::string json_path;  // "buffers[0].uri"
    std::string uri;        // as written
    std::string decoded;    // %XX decoded, as tinygltf will ask for it
    bool is_buffer = false;
    uint64_t byte_length = 0;  // a buffer's declared byteLength: the file must be that long
};

// `bytes` is the whole file; `binary` when it starts with the GLB magic "glTF".
// Checks, in order: GLB header, JSON depth and array sizes (a byte scan, gltf_json_scan.h),
// JSON syntax, asset.version (2.x), extensionsRequired (supported or ignorable), the JSON types
// of the core glTF properties, data: URIs, and that every image's buffer view lies inside its
// buffer's byteLength (tinygltf hands the image decoder those bytes unchecked).
// Returns the files the document references, for the caller to check before tinygltf reads.
std::vector<FileRef> precheck_gltf(std::string_view bytes, bool binary);

// A GLB container's JSON chunk (header and first chunk checked).
std::string_view glb_json_chunk(std::string_view bytes);

// The JSON text without a GLB chunk's padding (spaces; some writers pad with NULs).
std::string_view without_padding(std::string_view text);

}  // namespace ds::scene::detail
