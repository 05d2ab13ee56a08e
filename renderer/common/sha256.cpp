#include "renderer/common/sha256.h"

#include <cstring>
#include <fstream>
#include <vector>

#include <nettle/sha2.h>

#include "renderer/common/error.h"
#include "renderer/common/quoted.h"

namespace ds {

struct Sha256::State {
    sha256_ctx ctx;
};

Sha256::Sha256() : state_(std::make_unique<State>()) {
    sha256_init(&state_->ctx);
}

Sha256::~Sha256() = default;

void Sha256::update(const void* data, size_t bytes) {
    sha256_update(&state_->ctx, bytes, static_cast<const uint8_t*>(data));
}

std::array<uint8_t, 32> Sha256::finish() {
    std::array<uint8_t, 32> digest{};
    sha256_digest(&state_->ctx, digest.size(), digest.data());
    return digest;
}

std::string to_hex(const std::array<uint8_t, 32>& digest) {
    static const char* kHex = "0123456789abcdef";
    std::string out;
    for (const uint8_t b : digest) {
        out += kHex[b >> 4];
        out += kHex[b & 15];
    }
    return out;
}

std::string sha256_hex(std::string_view data) {
    Sha256 hash;
    hash.update(data.data(), data.size());
    return to_hex(hash.finish());
}

std::string sha256_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(escaped(path.string()) + ": cannot read");
    Sha256 hash;
    std::vector<char> chunk(1 << 16);
    while (in) {
        in.read(chunk.data(), std::streamsize(chunk.size()));
        hash.update(chunk.data(), size_t(in.gcount()));
    }
    if (in.bad()) throw Error(escaped(path.string()) + ": cannot read");
    return to_hex(hash.finish());
}

}  // namespace ds
