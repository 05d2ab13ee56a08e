#pragma once
// Every size and count the glTF importer accepts, in one place (listed in
// docs/reference/commands.md). Each is checked before the thing it bounds is read, decoded or
// allocated, so a hostile or broken file costs at most a bounded amount of time and memory and
// gives one error line. They sit far above real assets: a large production scene has a few thousand
// nodes, textures of 4096 or 8192 per side and a few million vertices per mesh.
#include <cstddef>
#include <cstdint>

namespace ds::scene::limits {

// The scene file itself and every buffer or image file it references (each). A file must also
// be a regular file: directories, FIFOs, devices and sockets are refused before opening.
inline constexpr uint64_t kMaxFileBytes = uint64_t{1} << 30;  // 1 GiB

// Nesting of JSON objects and arrays anywhere in the document, extras and extensions included
// (core glTF nests about 8 deep). Checked by a byte scan before any JSON parser sees the text:
// both nlohmann::json and tinygltf recurse per level.
inline constexpr int kMaxJsonDepth = 64;

// Entries of the top-level `nodes` array, and of each other top-level array (meshes,
// accessors, materials, images, ...). Counted by the same byte scan, before parsing.
inline constexpr size_t kMaxNodes = 65536;
inline constexpr size_t kMaxArrayEntries = 65536;

// Depth of the node hierarchy below a scene root (a 10,000-deep chain is not a model).
inline constexpr size_t kMaxHierarchyDepth = 1024;

// Images: width and height each, texels per image, and decoded bytes of all images together.
// Read from the image header before decoding (a small PNG may declare 100000 x 100000).
inline constexpr int kMaxImageSide = 16384;
inline constexpr uint64_t kMaxImageTexels = uint64_t{8192} * 8192;  // 64 Mi texels
inline constexpr uint64_t kMaxTotalImageBytes = uint64_t{1} << 30;  // 1 GiB decoded

// Elements of one accessor: 2^25 is ~100x a large real mesh. An accessor without a buffer view
// (zeros, perhaps patched by a sparse block) costs nothing in the file, so it gets less.
inline constexpr size_t kMaxAccessorElements = size_t{1} << 25;
inline constexpr size_t kMaxZeroAccessorElements = size_t{1} << 22;

}  // namespace ds::scene::limits
