#pragma once
// SHA-256 (FIPS 180-4), for what a capture records of a scene file so that a replay can tell
// the file changed. Small and dependency-free: the only hash the project needs.
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace ds {

class Sha256 {
  public:
    Sha256();
    void update(const void* data, size_t bytes);
    std::array<uint8_t, 32> finish();  // once; the object is spent afterwards

  private:
    void block(const uint8_t* p);
    std::array<uint32_t, 8> h_;
    std::array<uint8_t, 64> buffer_{};
    size_t used_ = 0;
    uint64_t total_ = 0;
};

std::string to_hex(const std::array<uint8_t, 32>& digest);
std::string sha256_hex(std::string_view data);
// The file's digest, read in blocks; throws ds::Error "PATH: cannot read" on failure.
std::string sha256_file(const std::filesystem::path& path);

}  // namespace ds
