#pragma once
// Where a glTF document's referenced files (buffer and image uris) come from: the disk next to
// the document, or a set of named files in memory (load_gltf_memory, the fuzzer). tinygltf
// reads them only through FsBridge, so no library ever opens an unchecked path: a file must be
// a regular file (never a directory, FIFO, device or socket) of at most kMaxFileBytes, opened
// without blocking. Internal to renderer/scene; errors are InputError with a WHAT only.
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace ds::scene::detail {

// Reads a whole file from disk after checking it (stat, then open with O_NONBLOCK, then fstat
// again in case it changed in between).
std::string read_regular_file(const std::filesystem::path& path);

class FileSource {
  public:
    virtual ~FileSource() = default;
    // `uri` is decoded (%XX) and relative to the document, or an absolute path.
    // Exists, is a regular file within kMaxFileBytes: returns its size.
    virtual uint64_t check(const std::string& uri) const = 0;
    virtual std::string read(const std::string& uri) const = 0;
};

class DiskSource : public FileSource {
  public:
    explicit DiskSource(std::filesystem::path base_dir) : base_dir_(std::move(base_dir)) {}
    uint64_t check(const std::string& uri) const override;
    std::string read(const std::string& uri) const override;

  private:
    std::filesystem::path resolve(const std::string& uri) const;
    std::filesystem::path base_dir_;
};

class MemorySource : public FileSource {
  public:
    // Names as they appear in uris (a leading "./" is ignored).
    explicit MemorySource(const std::map<std::string, std::string>& files) : files_(files) {}
    uint64_t check(const std::string& uri) const override;
    std::string read(const std::string& uri) const override;

  private:
    const std::string& find(const std::string& uri) const;
    const std::map<std::string, std::string>& files_;
};

// tinygltf's FsCallbacks over a FileSource. tinygltf is given an empty base dir, so the uri it
// asks for is the (decoded) uri itself; the source resolves it. The first failure is kept in
// `error` ("uri \"X\": WHAT"): tinygltf's own message for it is less clear.
struct FsBridge {
    const FileSource* source = nullptr;
    std::string error;
    tinygltf::FsCallbacks callbacks();
};

// glTF uris are percent-encoded; tinygltf decodes them the same way before reading.
std::string decode_uri(const std::string& uri);

}  // namespace ds::scene::detail
