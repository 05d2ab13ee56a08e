#pragma once
// The malformed-file corpus (issue 12): files derived at test time from a valid export of the
// built-in `foliage` scene (glTF + .bin + three PNG textures), each broken in one way. Every one
// must be refused by the real executable with one `depthscope: error:` line.
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ds::test::corpus {

namespace fs = std::filesystem;
using nlohmann::json;

// A folder holding a fresh copy of the valid export: scene.gltf, scene.bin, and the PNGs.
class Workspace {
  public:
    Workspace(fs::path dir, const fs::path& base);
    const fs::path& dir() const { return dir_; }
    json doc() const;  // scene.gltf parsed
    std::string bin() const;
    // Writes `doc` as `name` (default scene.gltf) and returns its path.
    fs::path write_gltf(const json& doc, const std::string& name = "scene.gltf") const;
    fs::path write(const std::string& name, const std::string& bytes) const;
    // scene.gltf + scene.bin as one GLB (the buffer becomes the BIN chunk).
    std::string glb(const json& doc, const std::string& bin) const;
    // Byte offset of accessor `index`'s data in scene.bin.
    size_t accessor_offset(const json& doc, int index) const;

  private:
    fs::path dir_;
};

struct Case {
    std::string name;    // test name: [a-z0-9_]
    std::string reason;  // why the file is broken (printed on failure)
    std::string expect;  // a part of the error message (the JSON path, byte offset or uri)
    std::function<fs::path(const Workspace&)> make;  // returns the scene path to load
};

// gtest prints a case by its name and reason (not its bytes).
inline void PrintTo(const Case& c, std::ostream* os) {
    *os << c.name << " (" << c.reason << ")";
}

std::vector<Case> json_cases();        // malformed_cases_json.cpp
std::vector<Case> binary_cases();      // malformed_cases_binary.cpp
std::vector<Case> compressed_cases();  // malformed_cases_compressed.cpp
std::vector<Case> all_cases();

}  // namespace ds::test::corpus
