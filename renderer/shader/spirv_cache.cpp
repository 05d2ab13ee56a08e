#include "renderer/shader/spirv_cache.h"

#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>

#include "renderer/shader/hash.h"

namespace ds::shader {

namespace fs = std::filesystem;

namespace {

// Entry layout (host byte order; the cache is per machine): header, then the SPIR-V words.
struct EntryHeader {
    char magic[8];
    uint64_t key;
    uint64_t word_count;
    uint64_t checksum;  // of the SPIR-V bytes: catches truncation and bit rot
};
constexpr char kEntryMagic[8] = {'D', 'S', 'S', 'P', 'I', 'R', 'V', '1'};
constexpr uint64_t kMaxWords = 64ull << 20;  // 256 MiB: anything bigger is garbage

uint64_t checksum_of(const std::vector<uint32_t>& spirv) {
    return Hasher().bytes(spirv.data(), spirv.size() * sizeof(uint32_t)).digest();
}

std::string hex16(uint64_t value) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
    return text;
}

// Unique per process and call, so concurrent writers (threads or processes) never share one.
fs::path temp_path_for(const fs::path& entry) {
    static std::atomic<uint64_t> counter{0};
    return entry.string() + ".tmp." + std::to_string(::getpid()) + "." +
           std::to_string(counter.fetch_add(1));
}

bool write_entry(const fs::path& path, uint64_t key, const std::vector<uint32_t>& spirv) {
    EntryHeader header{};
    std::memcpy(header.magic, kEntryMagic, sizeof kEntryMagic);
    header.key = key;
    header.word_count = spirv.size();
    header.checksum = checksum_of(spirv);
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) return false;
    out.write(reinterpret_cast<const char*>(&header), sizeof header);
    out.write(reinterpret_cast<const char*>(spirv.data()),
              static_cast<std::streamsize>(spirv.size() * sizeof(uint32_t)));
    out.close();
    return !out.fail();
}

}  // namespace

fs::path SpirvCache::entry_path(uint64_t key) const {
    return dir_ / (hex16(key) + ".spv");
}

std::optional<std::vector<uint32_t>> SpirvCache::load(uint64_t key) const {
    if (!enabled()) return std::nullopt;
    std::ifstream in(entry_path(key), std::ios::binary);
    if (!in) return std::nullopt;
    EntryHeader header{};
    if (!in.read(reinterpret_cast<char*>(&header), sizeof header)) return std::nullopt;
    if (std::memcmp(header.magic, kEntryMagic, sizeof kEntryMagic) != 0 || header.key != key ||
        header.word_count < 5 || header.word_count > kMaxWords) {
        return std::nullopt;
    }
    std::vector<uint32_t> spirv(header.word_count);
    const auto bytes = static_cast<std::streamsize>(spirv.size() * sizeof(uint32_t));
    if (!in.read(reinterpret_cast<char*>(spirv.data()), bytes)) return std::nullopt;
    if (in.peek() != std::ifstream::traits_type::eof()) return std::nullopt;  // trailing bytes
    if (spirv[0] != kSpirvMagic || checksum_of(spirv) != header.checksum) return std::nullopt;
    return spirv;
}

bool SpirvCache::store(uint64_t key, const std::vector<uint32_t>& spirv) const {
    if (!enabled()) return false;
    std::error_code ec;
    fs::create_directories(dir_, ec);
    if (ec) return false;
    const fs::path entry = entry_path(key);
    const fs::path temp = temp_path_for(entry);
    if (write_entry(temp, key, spirv)) {
        fs::rename(temp, entry, ec);  // atomic on POSIX: old or new entry, never a mix
        if (!ec) return true;
    }
    fs::remove(temp, ec);
    return false;
}

}  // namespace ds::shader
