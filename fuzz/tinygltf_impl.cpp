// tinygltf's implementation for the fuzz targets: without stb (the importer brings its own
// checked image loader) and without a file system (the importer's FsCallbacks serve memory):
// TINYGLTF_NO_* are set for every file of ds_fuzz_import (CMakeLists.txt), as the TinyGLTF
// class's defaults depend on them.
// TINYGLTF_NO_FS drops <fstream>, which the (unused) writer still needs.
#include <fstream>

#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
