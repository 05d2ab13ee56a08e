#pragma once
// A glTF whose best alpha cutoff is known by construction (tune alpha's test): one MASK quad,
// "cards", cutoff 0.5, facing a camera that sees its 256x256 texture at 4 texels per pixel
// (64 px across a 128x128 frame, so mip level 2 is sampled, nearest filtering). Each 4x4 block
// of level 0 has k texels of alpha kOn and 16 - k of 0, k growing from 0 to 15 across the
// quad. The reference (level 0, 4x4 samples per pixel) covers a pixel when k >= 8; level 2 holds
// the block's mean kOn * k / 16, so a cutoff in (kOn * 7/16, kOn * 8/16] covers the same
// pixels: with kOn = 0.64, (0.28, 0.32], whose middle 0.30 lies on tune's sweep.
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "capture/image_writer.h"

namespace ds::test {

struct TuneScene {
    std::filesystem::path gltf;
    std::string size = "128x128";
    double best_cutoff = 0.30;
};

inline std::vector<uint8_t> tune_scene_texture(uint32_t side, double on_alpha) {
    std::vector<uint8_t> rgba(size_t(side) * side * 4);
    for (uint32_t y = 0; y < side; ++y)
        for (uint32_t x = 0; x < side; ++x) {
            const uint32_t k = (x / 4) * 16 / (side / 4);  // 0..15 across
            const uint32_t index = (y % 4) * 4 + (x % 4);  // the texel's place in its block
            uint8_t* t = &rgba[(size_t(y) * side + x) * 4];
            t[0] = 40, t[1] = 160, t[2] = 60;
            t[3] = index < k ? uint8_t(std::lround(on_alpha * 255.0)) : 0;
        }
    return rgba;
}

inline nlohmann::json tune_scene_json(double distance) {
    using nlohmann::json;
    const json position = {{"bufferView", 0}, {"componentType", 5126},    {"count", 4},
                           {"type", "VEC3"},  {"min", {-0.5, -0.5, 0.0}}, {"max", {0.5, 0.5, 0.0}}};
    return {
        {"asset", {{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", {{{"nodes", {0, 1}}}}},
        {"nodes",
         {{{"name", "eye"}, {"camera", 0}, {"translation", {0.0, 0.0, distance}}},
          {{"name", "cards"}, {"mesh", 0}}}},
        {"cameras",
         {{{"type", "perspective"},
           {"perspective", {{"yfov", 0.8}, {"znear", 0.1}, {"zfar", 100.0}}}}}},
        {"meshes",
         json::array(
             {{{"name", "quad"},
               {"primitives",
                json::array({{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}}},
                              {"indices", 3},
                              {"material", 0}}})}}})},
        {"materials",
         {{{"name", "cards"},
           {"alphaMode", "MASK"},
           {"alphaCutoff", 0.5},
           {"doubleSided", true},
           {"pbrMetallicRoughness",
            {{"baseColorTexture", {{"index", 0}}}, {"metallicFactor", 0.0}}}}}},
        {"textures", {{{"source", 0}, {"sampler", 0}}}},
        {"samplers",
         {{{"magFilter", 9728}, {"minFilter", 9984}}}},  // NEAREST, NEAREST_MIPMAP_NEAREST
        {"images", {{{"uri", "cards.png"}}}},
        {"buffers", {{{"uri", "quad.bin"}, {"byteLength", 140}}}},
        {"bufferViews",
         {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 48}},
          {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 48}},
          {{"buffer", 0}, {"byteOffset", 96}, {"byteLength", 32}},
          {{"buffer", 0}, {"byteOffset", 128}, {"byteLength", 12}}}},
        {"accessors",
         {position,
          {{"bufferView", 1}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
          {{"bufferView", 2}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}},
          {{"bufferView", 3}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}}},
    };
}

inline TuneScene write_tune_scene(const std::filesystem::path& dir) {
    const float pos[12] = {-0.5f, -0.5f, 0, 0.5f, -0.5f, 0, 0.5f, 0.5f, 0, -0.5f, 0.5f, 0};
    const float nrm[12] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
    const float uv[8] = {0, 1, 1, 1, 1, 0, 0, 0};
    const uint16_t idx[6] = {0, 1, 2, 0, 2, 3};
    std::ofstream bin(dir / "quad.bin", std::ios::binary);
    bin.write(reinterpret_cast<const char*>(pos), sizeof pos);
    bin.write(reinterpret_cast<const char*>(nrm), sizeof nrm);
    bin.write(reinterpret_cast<const char*>(uv), sizeof uv);
    bin.write(reinterpret_cast<const char*>(idx), sizeof idx);
    bin.close();
    capture::write_png_rgba8(dir / "cards.png", 256, 256, tune_scene_texture(256, 0.64));
    // The quad (1 unit) spans half the frame's height: 2 d tan(yfov / 2) = 2.
    const double distance = 1.0 / std::tan(0.4);
    std::ofstream(dir / "cards.gltf") << tune_scene_json(distance).dump();
    return {dir / "cards.gltf"};
}

}  // namespace ds::test
