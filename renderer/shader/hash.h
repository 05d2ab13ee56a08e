#pragma once
// 64-bit FNV-1a, used for SPIR-V cache keys and cache-entry checksums. Not cryptographic: a
// cache key only has to change when an input changes, and a collision costs a wrong cache hit
// with probability ~2^-64 per pair of inputs.
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace ds::shader {

class Hasher {
  public:
    static constexpr uint64_t kOffsetBasis = 14695981039346656037ull;
    static constexpr uint64_t kPrime = 1099511628211ull;

    Hasher& bytes(const void* data, size_t size) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < size; ++i) {
            state_ = (state_ ^ p[i]) * kPrime;
        }
        return *this;
    }

    // Little-endian regardless of the host, so keys mean the same thing everywhere.
    Hasher& u64(uint64_t value) {
        unsigned char le[8];
        for (int i = 0; i < 8; ++i) le[i] = static_cast<unsigned char>(value >> (8 * i));
        return bytes(le, sizeof le);
    }

    // Length-prefixed, so ("ab","c") and ("a","bc") hash differently.
    Hasher& field(std::string_view text) {
        u64(text.size());
        return bytes(text.data(), text.size());
    }

    uint64_t digest() const { return state_; }

  private:
    uint64_t state_ = kOffsetBasis;
};

}  // namespace ds::shader
