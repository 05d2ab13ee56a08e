#pragma once
// Procedural RGBA8 textures for the built-in scenes. Small (64-256 px) and deterministic (a
// fixed integer hash, no global random state) so every build gives the same pixels.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace ds::scene::builtin {

struct Pixels {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> rgba;  // width * height * 4, row 0 at the top

    Pixels(int w, int h) : width(w), height(h), rgba(static_cast<size_t>(w) * h * 4, 0) {}
    void set(int x, int y, const glm::vec4& c);  // c in 0..1, clamped
};

float hash01(uint32_t x, uint32_t y, uint32_t seed);
// Deterministic value noise in [0, 1]; period > 0 wraps the lattice so textures tile.
float value_noise(float x, float y, uint32_t seed, int period = 0);

Pixels brick_texture(int size, const glm::vec3& brick, const glm::vec3& mortar, uint32_t seed);
Pixels brick_normal_map(int size);
Pixels stone_tile_texture(int size, const glm::vec3& base, uint32_t seed);
Pixels sandstone_texture(int size, const glm::vec3& base, uint32_t seed);
Pixels marble_texture(int size, const glm::vec3& base, uint32_t seed);
Pixels wood_texture(int size, const glm::vec3& light, const glm::vec3& dark, uint32_t seed);
// Grey weave; the material's base colour factor tints it.
Pixels fabric_texture(int size, uint32_t seed);
// Leaves on a transparent background: alpha is exactly 0 or 1 (crisp for MASK).
Pixels leaf_texture(int size, uint32_t seed);
// Grass blades on a transparent background, one blade per 4 texels across, each a few texels
// wide at its root and tapering to nothing, edges antialiased: the thin cut-outs that a box
// filter's mips average away (foliage's grass, alpha_mip_coverage).
Pixels grass_texture(int size, uint32_t seed);
// Decals: a poster (opaque inside a soft-edged frame) and a stain (soft radial alpha).
Pixels poster_texture(int size, const glm::vec3& colour, uint32_t seed);
Pixels stain_texture(int size, uint32_t seed);
// Alpha = u (0 at the left edge, 1 at the right), optionally times a leaf silhouette.
Pixels alpha_gradient_texture(int size, bool leaf_shape);
Pixels checker_texture(int size, int cells, const glm::vec3& a, const glm::vec3& b);

}  // namespace ds::scene::builtin
