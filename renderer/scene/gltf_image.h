#pragma once
// The image decoder the importer gives tinygltf (TinyGLTF::SetImageLoader): PNG and JPEG only
// (the formats core glTF allows), with the header read first so that dimensions beyond
// import_limits.h are refused before anything is decoded or allocated.
// Internal to renderer/scene.
#include <cstdint>
#include <map>
#include <string>

#include <tiny_gltf.h>

namespace ds::scene::detail {

struct ImageBudget {
    uint64_t decoded_bytes = 0;  // all images so far (bounded by kMaxTotalImageBytes)
    std::string error;           // the first refusal: "images[N]: WHAT"
    // Lenient (not --strict): an image that does not decode is recorded here, by index, and
    // left without pixels; the importer drops the textures that use it with a warning.
    bool lenient = false;
    std::map<size_t, std::string> problems;
    // Image files the document names that are not there (decoded uri -> why), read as a
    // one-byte placeholder so that tinygltf goes on; their problem is this text.
    std::map<std::string, std::string> missing;
};

// tinygltf::LoadImageDataFunction; `user` is an ImageBudget. Decodes to 4 channels of 8 or
// 16 bits, as tinygltf's own loader does.
bool load_image_checked(tinygltf::Image* image, int index, std::string* err, std::string* warn,
                        int req_width, int req_height, const unsigned char* bytes, int size,
                        void* user);

}  // namespace ds::scene::detail
