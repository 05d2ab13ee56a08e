// Builds the importer's seed corpus: `fuzz_pack OUT_DIR MAX_BYTES PATH...` finds every .gltf
// and .glb under the PATHs and writes each, with the files its buffers and images name, as one
// fuzz input (container.h) into OUT_DIR; inputs over MAX_BYTES are skipped. Prints a count.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "container.h"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::string json_text(const std::string& doc) {
    if (!doc.starts_with("glTF") || doc.size() < 20) return doc;
    const auto* p = reinterpret_cast<const unsigned char*>(doc.data());
    const uint32_t length = p[12] | p[13] << 8 | p[14] << 16 | uint32_t(p[15]) << 24;
    return doc.substr(20, length);
}

std::string percent_decode(const std::string& uri) {
    std::string out;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size()) {
            out += static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

// The document and its referenced files; false when something is missing or unreadable.
bool collect(const fs::path& path, ds::fuzz::Container& c) {
    c.name = path.filename().string();
    c.document = read(path);
    try {
        const json doc = json::parse(json_text(c.document));
        for (const char* array : {"buffers", "images"}) {
            if (!doc.contains(array)) continue;
            for (const json& entry : doc[array]) {
                if (!entry.contains("uri")) continue;
                const std::string uri = entry["uri"].get<std::string>();
                if (uri.starts_with("data:")) continue;
                const std::string name = percent_decode(uri);
                const fs::path file = path.parent_path() / name;
                if (!fs::is_regular_file(file)) return false;
                c.files[name] = read(file);
            }
        }
    } catch (const std::exception&) {
        return true;  // broken JSON is a seed too
    }
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: fuzz_pack OUT_DIR MAX_BYTES PATH...\n");
        return 2;
    }
    const fs::path out = argv[1];
    const size_t max_bytes = std::strtoull(argv[2], nullptr, 10);
    fs::create_directories(out);
    size_t written = 0;
    auto take = [&](const fs::path& path) {
        const auto ext = path.extension();
        if (ext != ".gltf" && ext != ".glb") return;
        ds::fuzz::Container c;
        if (!collect(path, c)) return;
        const std::string bytes = ds::fuzz::pack(c);
        if (bytes.size() > max_bytes) return;
        const size_t hash = std::hash<std::string>{}(bytes);
        std::ofstream(out / ("seed-" + std::to_string(hash)), std::ios::binary) << bytes;
        ++written;
    };
    for (int i = 3; i < argc; ++i) {
        const fs::path root = argv[i];
        if (fs::is_directory(root)) {
            for (const auto& entry : fs::recursive_directory_iterator(root))
                if (entry.is_regular_file()) take(entry.path());
        } else {
            take(root);
        }
    }
    std::printf("%zu seeds in %s\n", written, out.c_str());
    return 0;
}
