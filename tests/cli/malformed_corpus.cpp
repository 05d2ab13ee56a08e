#include "malformed_corpus.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace ds::test::corpus {
namespace {

std::string slurp(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + path.string());
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

void put_u32(std::string& out, uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>(v >> (8 * i)));
}

}  // namespace

// The export's file names follow the scene (foliage.bin, foliage_*.png); the copy renames the
// document and buffer to scene.gltf / scene.bin so that cases read alike.
Workspace::Workspace(fs::path dir, const fs::path& base) : dir_(std::move(dir)) {
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    for (const auto& entry : fs::directory_iterator(base)) {
        const std::string name = entry.path().filename().string();
        if (name.ends_with(".png")) fs::copy_file(entry.path(), dir_ / name);
    }
    json d = json::parse(slurp(base / "foliage.gltf"));
    d["buffers"][0]["uri"] = "scene.bin";
    write_gltf(d);
    write("scene.bin", slurp(base / "foliage.bin"));
}

json Workspace::doc() const {
    return json::parse(slurp(dir_ / "scene.gltf"));
}

std::string Workspace::bin() const {
    return slurp(dir_ / "scene.bin");
}

fs::path Workspace::write_gltf(const json& doc, const std::string& name) const {
    return write(name, doc.dump(1));
}

fs::path Workspace::write(const std::string& name, const std::string& bytes) const {
    const fs::path path = dir_ / name;
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
    return path;
}

std::string Workspace::glb(const json& doc, const std::string& bin) const {
    json d = doc;
    d["buffers"][0].erase("uri");
    std::string text = d.dump();
    while (text.size() % 4 != 0) text.push_back(' ');
    std::string data = bin;
    while (data.size() % 4 != 0) data.push_back('\0');
    std::string out = "glTF";
    put_u32(out, 2);
    put_u32(out, static_cast<uint32_t>(12 + 8 + text.size() + 8 + data.size()));
    put_u32(out, static_cast<uint32_t>(text.size()));
    out += "JSON" + text;
    put_u32(out, static_cast<uint32_t>(data.size()));
    out += std::string("BIN\0", 4) + data;
    return out;
}

size_t Workspace::accessor_offset(const json& doc, int index) const {
    const json& accessor = doc["accessors"][static_cast<size_t>(index)];
    const json& view = doc["bufferViews"][accessor["bufferView"].get<size_t>()];
    return view.value("byteOffset", size_t{0}) + accessor.value("byteOffset", size_t{0});
}

std::vector<Case> all_cases() {
    std::vector<Case> cases = json_cases();
    for (Case& c : binary_cases()) cases.push_back(std::move(c));
    for (Case& c : compressed_cases()) cases.push_back(std::move(c));
    return cases;
}

}  // namespace ds::test::corpus
