// Debugging aid, not a check: with DS_BUILTIN_VIEWS=DIR set, writes for every scene a flat-
// shaded camera view (nearest surface, material colour) and a depth-complexity heat map, plus a
// top-down view of the atrium, as PNGs to look at. Skipped otherwise.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <stb/stb_image_write.h>

#include "model_view.h"
#include "raster.h"
#include "renderer/scene/builtin/builtin.h"

namespace ds::scene::builtin {
namespace {

// Material colour: base colour factor times the mean of its base colour texture.
std::vector<glm::vec3> material_colours(const tinygltf::Model& m) {
    std::vector<glm::vec3> out;
    for (const tinygltf::Material& mat : m.materials) {
        const auto& f = mat.pbrMetallicRoughness.baseColorFactor;
        glm::vec3 c(f[0], f[1], f[2]);
        const int tex = mat.pbrMetallicRoughness.baseColorTexture.index;
        if (tex >= 0) {
            const tinygltf::Image& img = m.images.at(m.textures.at(tex).source);
            glm::dvec3 sum(0.0);
            double weight = 0.0;
            for (size_t i = 0; i + 3 < img.image.size(); i += 4) {
                const double a = img.image[i + 3] / 255.0;
                sum += glm::dvec3(img.image[i], img.image[i + 1], img.image[i + 2]) * a / 255.0;
                weight += a;
            }
            if (weight > 0.0) c *= glm::vec3(sum / weight);
        }
        out.push_back(c);
    }
    return out;
}

void write_png(const std::filesystem::path& path, int w, int h, const std::vector<uint8_t>& rgb) {
    ASSERT_NE(stbi_write_png(path.c_str(), w, h, 3, rgb.data(), w * 3), 0) << path;
}

void write_shaded(const std::filesystem::path& path, const tinygltf::Model& m,
                  const std::vector<test::WorldTriangle>& tris, const test::Coverage& c) {
    const std::vector<glm::vec3> colours = material_colours(m);
    const glm::vec3 to_sun = glm::normalize(glm::vec3(0.3f, 1.0f, 0.4f));
    std::vector<uint8_t> rgb(static_cast<size_t>(c.width) * c.height * 3);
    for (size_t i = 0; i < c.nearest.size(); ++i) {
        glm::vec3 col(0.55f, 0.7f, 0.9f);  // sky
        if (c.nearest[i] >= 0) {
            const test::WorldTriangle& t = tris[static_cast<size_t>(c.nearest[i])];
            const glm::vec3 n = glm::normalize(glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]));
            const float lambert = t.double_sided ? std::abs(glm::dot(n, to_sun))
                                                 : std::max(0.0f, glm::dot(n, to_sun));
            col = colours.at(static_cast<size_t>(t.material)) * (0.35f + 0.65f * lambert);
        }
        for (int k = 0; k < 3; ++k) {
            rgb[i * 3 + k] = static_cast<uint8_t>(std::clamp(col[k], 0.0f, 1.0f) * 255.0f);
        }
    }
    write_png(path, c.width, c.height, rgb);
}

void write_heat(const std::filesystem::path& path, const test::Coverage& c) {
    // 0 black, 1 blue, 2 cyan, 3 green, 4 yellow, 5-6 red, 8+ white.
    const glm::vec3 ramp[] = {{0, 0, 0},    {0, 0, 1}, {0, 1, 1}, {0, 1, 0}, {1, 1, 0},
                              {1, 0.5f, 0}, {1, 0, 0}, {1, 0, 1}, {1, 1, 1}};
    std::vector<uint8_t> rgb(static_cast<size_t>(c.width) * c.height * 3);
    for (size_t i = 0; i < c.fragments.size(); ++i) {
        const glm::vec3 col = ramp[std::min<uint32_t>(c.fragments[i], 8)];
        for (int k = 0; k < 3; ++k) rgb[i * 3 + k] = static_cast<uint8_t>(col[k] * 255.0f);
    }
    write_png(path, c.width, c.height, rgb);
}

TEST(BuiltinViews, WriteDebugImages) {
    const char* dir = std::getenv("DS_BUILTIN_VIEWS");
    if (dir == nullptr) GTEST_SKIP() << "set DS_BUILTIN_VIEWS=DIR to write debug images";
    std::filesystem::create_directories(dir);
    for (const Info& info : list()) {
        const tinygltf::Model m = build(info.name, Settings());
        const auto tris = test::world_triangles(m);
        const auto cam = test::find_camera(m);
        ASSERT_TRUE(cam.has_value());
        const test::Coverage c = test::rasterise(tris, *cam, {480, 270, true});
        write_shaded(std::filesystem::path(dir) / (info.name + "_view.png"), m, tris, c);
        write_heat(std::filesystem::path(dir) / (info.name + "_heat.png"), c);
        std::printf("%s: depth complexity %.2f\n", info.name.c_str(), c.depth_complexity());
        if (info.name == "atrium") {
            const test::ViewCamera top =
                test::look_at({0.0f, 70.0f, 0.1f}, {0.0f, 0.0f, 0.0f}, 0.6f, 16.0f / 9.0f);
            write_shaded(std::filesystem::path(dir) / "atrium_top.png", m, tris,
                         test::rasterise(tris, top, {480, 270, true}));
            const test::ViewCamera corner =
                test::look_at({-4.0f, 14.0f, 20.0f}, {0.0f, 3.0f, 0.0f}, 1.0f, 16.0f / 9.0f);
            write_shaded(std::filesystem::path(dir) / "atrium_high.png", m, tris,
                         test::rasterise(tris, corner, {480, 270, true}));
        }
    }
}

}  // namespace
}  // namespace ds::scene::builtin
