#pragma once
// On-disk SPIR-V cache: one file per key. Best effort by design: an unreadable, corrupt or
// unwritable cache only costs a compile, it never fails one.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

namespace ds::shader {

constexpr uint32_t kSpirvMagic = 0x07230203;

class SpirvCache {
  public:
    // An empty dir disables the cache. The folder is created on the first store.
    explicit SpirvCache(std::filesystem::path dir) : dir_(std::move(dir)) {}

    bool enabled() const { return !dir_.empty(); }
    std::filesystem::path entry_path(uint64_t key) const;

    // The entry for `key`, or nullopt when it is missing, truncated, corrupt or unreadable.
    std::optional<std::vector<uint32_t>> load(uint64_t key) const;
    // Writes a temp file and renames it over the entry, so readers never see half a file.
    // Returns false (and leaves no temp file) when that is not possible.
    bool store(uint64_t key, const std::vector<uint32_t>& spirv) const;

  private:
    std::filesystem::path dir_;
};

}  // namespace ds::shader
