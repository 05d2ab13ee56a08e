#pragma once
// The image decoder the importer gives tinygltf (TinyGLTF::SetImageLoader): PNG and JPEG only
// (the formats core glTF allows), with the header read first so that dimensions beyond
// import_limits.h are refused before anything is decoded or allocated.
// Internal to renderer/scene.
#include <cstdint>
#include <string>

#include <tiny_gltf.h>

namespace ds::scene::detail {

struct ImageBudget {
    uint64_t decoded_bytes = 0;  // all images so far (bounded by kMaxTotalImageBytes)
    std::string error;           // the first refusal: "images[N]: WHAT"
};

// tinygltf::LoadImageDataFunction; `user` is an ImageBudget. Decodes to 4 channels of 8 or
// 16 bits, as tinygltf's own loader does.
bool load_image_checked(tinygltf::Image* image, int index, std::string* err, std::string* warn,
                        int req_width, int req_height, const unsigned char* bytes, int size,
                        void* user);

}  // namespace ds::scene::detail
