#pragma once
// SHA-256, for what a capture records of a scene file so that a replay can tell the file
// changed: Nettle's (Debian's nettle-dev), behind this small interface.
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

namespace ds {

class Sha256 {
  public:
    Sha256();
    ~Sha256();
    Sha256(const Sha256&) = delete;
    Sha256& operator=(const Sha256&) = delete;
    void update(const void* data, size_t bytes);
    std::array<uint8_t, 32> finish();  // once; the object is spent afterwards

  private:
    struct State;
    std::unique_ptr<State> state_;
};

std::string to_hex(const std::array<uint8_t, 32>& digest);
std::string sha256_hex(std::string_view data);
// The file's digest, read in blocks; throws ds::Error "PATH: cannot read" on failure.
std::string sha256_file(const std::filesystem::path& path);

}  // namespace ds
