#pragma once
// Hand-made glTF files for lint's tests: unit squares (side 1, in the XY plane, facing +Z; two
// meshes with opposite diagonals) and a sliver (three collinear vertices), placed by nodes
// with a translation, a rotation and a uniform scale, each with a material of the test's
// choosing. Written as FILE.gltf + FILE.bin.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ds::test {

enum LintMesh : int { kSquare = 0, kSquareOtherDiagonal = 1, kSliver = 2 };

struct LintNode {
    std::string name;
    int mesh = kSquare;
    int material = 0;
    std::vector<double> translation{0, 0, 0};
    std::vector<double> rotation{0, 0, 0, 1};  // x, y, z, w
    double scale = 1.0;
};

struct LintMaterial {
    std::string name;
    std::string alpha_mode = "OPAQUE";
    double alpha = 1.0;  // baseColorFactor.a
    bool double_sided = false;
};

inline nlohmann::json lint_accessors() {
    using nlohmann::json;
    json out = json::array();
    // Per mesh: positions (4 vertices, 48 bytes) then indices (6 u16, 12 bytes); 60 bytes each.
    for (int m = 0; m < 3; ++m) {
        out.push_back({{"bufferView", 2 * m},
                       {"componentType", 5126},
                       {"count", 4},
                       {"type", "VEC3"},
                       {"min", {-0.5, -0.5, 0.0}},
                       {"max", {0.5, 0.5, 0.0}}});
        out.push_back(
            {{"bufferView", 2 * m + 1}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}});
    }
    return out;
}

inline void write_lint_bin(const std::filesystem::path& file) {
    const float square[12] = {-0.5f, -0.5f, 0, 0.5f, -0.5f, 0, 0.5f, 0.5f, 0, -0.5f, 0.5f, 0};
    const float sliver[12] = {-0.5f, -0.5f, 0, 0.0f, 0.0f, 0, 0.5f, 0.5f, 0, -0.5f, 0.5f, 0};
    const uint16_t diag_a[6] = {0, 1, 2, 0, 2, 3}, diag_b[6] = {0, 1, 3, 1, 2, 3};
    const uint16_t sliver_idx[6] = {0, 1, 2, 0, 2, 3};  // 0,1,2 collinear
    std::ofstream bin(file, std::ios::binary);
    const auto put = [&](const void* p, size_t n) {
        bin.write(static_cast<const char*>(p), long(n));
    };
    put(square, 48), put(diag_a, 12), put(square, 48), put(diag_b, 12), put(sliver, 48),
        put(sliver_idx, 12);
}

inline nlohmann::json lint_gltf(const std::vector<LintNode>& nodes,
                                const std::vector<LintMaterial>& materials,
                                const std::string& bin_name) {
    using nlohmann::json;
    json j = {{"asset", {{"version", "2.0"}}}, {"scene", 0}, {"accessors", lint_accessors()}};
    j["buffers"] = {{{"uri", bin_name}, {"byteLength", 180}}};
    for (int v = 0; v < 6; ++v)
        j["bufferViews"].push_back({{"buffer", 0},
                                    {"byteOffset", (v / 2) * 60 + (v % 2) * 48},
                                    {"byteLength", v % 2 ? 12 : 48}});
    const char* names[3] = {"square", "square_other_diagonal", "sliver"};
    for (int m = 0; m < 3; ++m)
        j["meshes"].push_back(
            {{"name", names[m]},
             {"primitives", {{{"attributes", {{"POSITION", 2 * m}}}, {"indices", 2 * m + 1}}}}});
    j["scenes"] = {{{"nodes", json::array()}}};
    for (size_t n = 0; n < nodes.size(); ++n) {
        const LintNode& node = nodes[n];
        // glTF gives a mesh one material per primitive: a mesh per (shape, material) pair.
        const int mesh = int(j["meshes"].size());
        json m = j["meshes"][size_t(node.mesh)];
        m["name"] = node.name + "_mesh";
        m["primitives"][0]["material"] = node.material;
        j["meshes"].push_back(m);
        j["nodes"].push_back({{"name", node.name},
                              {"mesh", mesh},
                              {"translation", node.translation},
                              {"rotation", node.rotation},
                              {"scale", {node.scale, node.scale, node.scale}}});
        j["scenes"][0]["nodes"].push_back(n);
    }
    for (const LintMaterial& m : materials)
        j["materials"].push_back(
            {{"name", m.name},
             {"alphaMode", m.alpha_mode},
             {"doubleSided", m.double_sided},
             {"pbrMetallicRoughness",
              {{"baseColorFactor", {0.8, 0.8, 0.8, m.alpha}}, {"metallicFactor", 0.0}}}});
    return j;
}

// Writes DIR/NAME.gltf and DIR/NAME.bin; returns the .gltf path.
inline std::filesystem::path write_lint_scene(const std::filesystem::path& dir,
                                              const std::string& name,
                                              const std::vector<LintNode>& nodes,
                                              const std::vector<LintMaterial>& materials) {
    write_lint_bin(dir / (name + ".bin"));
    std::ofstream(dir / (name + ".gltf")) << lint_gltf(nodes, materials, name + ".bin").dump(1);
    return dir / (name + ".gltf");
}

}  // namespace ds::test
