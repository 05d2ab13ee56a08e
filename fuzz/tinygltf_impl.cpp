// tinygltf's implementation for the fuzz targets: without stb (the importer brings its own
// checked image loader) and without a file system (the importer's FsCallbacks serve memory).
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_FS
#include <tiny_gltf.h>
