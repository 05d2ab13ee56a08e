#pragma once
// One fuzz input holding a glTF document and the files it references:
//   "DSFZ" { u8 name_length, name, u32 size (little endian), bytes }*
// The first entry is the document (its name is the one messages show), the rest are served to
// its uris by name. An input without the magic is a document with no files, so plain .gltf and
// .glb files are inputs too.
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>

namespace ds::fuzz {

struct Container {
    std::string name = "input.gltf";
    std::string document;
    std::map<std::string, std::string> files;
};

Container unpack(const uint8_t* data, size_t size);
std::string pack(const Container& container);

}  // namespace ds::fuzz
