#include "renderer/scene/builtin/textures.h"
#include "renderer/scene/builtin/angles.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ds::scene::builtin {

namespace {

uint32_t hash3(uint32_t x, uint32_t y, uint32_t s) {
    uint32_t h = x * 0x8da6b343u ^ y * 0xd8163841u ^ s * 0xcb1ab31fu;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return h;
}

// Two octaves of value noise; `period` lattice cells across the texture so it tiles.
float fbm(float u, float v, int period, uint32_t seed) {
    const auto p = static_cast<float>(period);
    return 0.65f * value_noise(u * p, v * p, seed, period) +
           0.35f * value_noise(u * p * 2.0f, v * p * 2.0f, seed + 17, period * 2);
}

float uv_of(int px, int size) {
    return (static_cast<float>(px) + 0.5f) / static_cast<float>(size);
}

// Brick layout shared by the colour and normal textures: 4 bricks across, 8 rows, half-brick
// offset on odd rows. Returns the distance (in bricks' pixels) to the nearest mortar line and
// the brick id.
struct BrickSample {
    float edge_distance;
    uint32_t id;
};
BrickSample brick_at(int x, int y, int size) {
    const int bw = size / 4, bh = size / 8;
    const int row = y / bh;
    const int xs = x + ((row & 1) ? bw / 2 : 0);
    const int col = (xs / bw) % 4;
    const int lx = xs % bw, ly = y % bh;
    const int d = std::min(std::min(lx, bw - 1 - lx), std::min(ly, bh - 1 - ly));
    return {static_cast<float>(d), static_cast<uint32_t>(row * 4 + col)};
}

// Unit-ish leaf silhouette in local coordinates: x along the leaf (0..1), y across.
bool inside_leaf(float x, float y, float width) {
    if (x < 0.0f || x > 1.0f) return false;
    const float half = width * std::pow(std::sin(kPi * x), 0.8f) * (1.0f - 0.3f * x);
    return std::abs(y) < half;
}

}  // namespace

void Pixels::set(int x, int y, const glm::vec4& c) {
    const size_t i = (static_cast<size_t>(y) * width + x) * 4;
    for (int k = 0; k < 4; ++k) {
        rgba[i + k] = static_cast<uint8_t>(std::clamp(c[k], 0.0f, 1.0f) * 255.0f + 0.5f);
    }
}

float hash01(uint32_t x, uint32_t y, uint32_t seed) {
    return static_cast<float>(hash3(x, y, seed)) / 4294967295.0f;
}

float value_noise(float x, float y, uint32_t seed, int period) {
    const float fx = std::floor(x), fy = std::floor(y);
    const float tx = x - fx, ty = y - fy;
    const float sx = tx * tx * (3.0f - 2.0f * tx), sy = ty * ty * (3.0f - 2.0f * ty);
    auto wrap = [period](float f, int add) {
        int i = static_cast<int>(f) + add;
        if (period > 0) i = ((i % period) + period) % period;
        return static_cast<uint32_t>(i);
    };
    const float a = hash01(wrap(fx, 0), wrap(fy, 0), seed);
    const float b = hash01(wrap(fx, 1), wrap(fy, 0), seed);
    const float c = hash01(wrap(fx, 0), wrap(fy, 1), seed);
    const float d = hash01(wrap(fx, 1), wrap(fy, 1), seed);
    return glm::mix(glm::mix(a, b, sx), glm::mix(c, d, sx), sy);
}

Pixels brick_texture(int size, const glm::vec3& brick, const glm::vec3& mortar, uint32_t seed) {
    Pixels p(size, size);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const BrickSample s = brick_at(x, y, size);
            const float grain = fbm(uv_of(x, size), uv_of(y, size), 16, seed);
            glm::vec3 c;
            if (s.edge_distance < 1.5f) {
                c = mortar * (0.85f + 0.3f * grain);
            } else {
                const float tint = 0.8f + 0.35f * hash01(s.id, 0, seed);
                c = brick * tint * (0.85f + 0.3f * grain);
            }
            p.set(x, y, glm::vec4(c, 1.0f));
        }
    }
    return p;
}

Pixels brick_normal_map(int size) {
    // Height: mortar low, bevelled brick edges; normals by central differences.
    std::vector<float> h(static_cast<size_t>(size) * size);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            h[static_cast<size_t>(y) * size + x] =
                std::min(brick_at(x, y, size).edge_distance, 3.0f) / 3.0f;
        }
    }
    auto at = [&](int x, int y) {
        return h[static_cast<size_t>((y + size) % size) * size + (x + size) % size];
    };
    Pixels p(size, size);
    const float strength = 1.5f;
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const float dx = (at(x + 1, y) - at(x - 1, y)) * 0.5f;
            const float drow = (at(x, y + 1) - at(x, y - 1)) * 0.5f;
            // Image rows grow downwards but tangent-space +Y is up (glTF), hence +drow.
            const glm::vec3 n = glm::normalize(glm::vec3(-dx * strength, drow * strength, 1.0f));
            p.set(x, y, glm::vec4(n * 0.5f + 0.5f, 1.0f));
        }
    }
    return p;
}

Pixels stone_tile_texture(int size, const glm::vec3& base, uint32_t seed) {
    Pixels p(size, size);
    const int tile = size / 4;
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const int lx = x % tile, ly = y % tile;
            const bool grout = lx < 2 || ly < 2;
            const uint32_t id = static_cast<uint32_t>((y / tile) * 4 + x / tile);
            const float n = fbm(uv_of(x, size), uv_of(y, size), 8, seed);
            const float tint = 0.82f + 0.3f * hash01(id, 1, seed);
            const glm::vec3 c = grout ? base * 0.45f : base * tint * (0.8f + 0.35f * n);
            p.set(x, y, glm::vec4(c, 1.0f));
        }
    }
    return p;
}

Pixels sandstone_texture(int size, const glm::vec3& base, uint32_t seed) {
    Pixels p(size, size);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const float u = uv_of(x, size), v = uv_of(y, size);
            // Horizontal strata disturbed by noise, plus a fine speckle.
            const float strata =
                0.5f + 0.5f * std::sin(v * 2.0f * kPi * 6.0f + 4.0f * fbm(u, v, 4, seed));
            const float speckle = hash01(static_cast<uint32_t>(x), static_cast<uint32_t>(y), seed);
            const glm::vec3 c = base * (0.82f + 0.14f * strata + 0.08f * speckle);
            p.set(x, y, glm::vec4(c, 1.0f));
        }
    }
    return p;
}

Pixels marble_texture(int size, const glm::vec3& base, uint32_t seed) {
    Pixels p(size, size);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const float u = uv_of(x, size), v = uv_of(y, size);
            const float turb = fbm(u, v, 6, seed);
            const float vein = std::pow(
                std::abs(std::sin((u + v * 0.5f) * 2.0f * kPi * 2.0f + 6.0f * turb)), 0.25f);
            const glm::vec3 c = base * (0.72f + 0.28f * vein);
            p.set(x, y, glm::vec4(c, 1.0f));
        }
    }
    return p;
}

Pixels wood_texture(int size, const glm::vec3& light, const glm::vec3& dark, uint32_t seed) {
    Pixels p(size, size);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const float u = uv_of(x, size), v = uv_of(y, size);
            // Grain runs along u (the beam's length); rings wobble with noise.
            const float rings =
                0.5f + 0.5f * std::sin(v * 2.0f * kPi * 10.0f + 5.0f * fbm(u, v, 6, seed));
            const float plank = (y / (size / 4)) % 2 ? 0.92f : 1.0f;
            p.set(x, y, glm::vec4(glm::mix(dark, light, rings) * plank, 1.0f));
        }
    }
    return p;
}

Pixels fabric_texture(int size, uint32_t seed) {
    Pixels p(size, size);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            // Plain weave: warp over weft on alternating 2x2 cells, with thread shading.
            const bool warp = ((x / 2) + (y / 2)) % 2 == 0;
            const float thread = warp ? 0.5f + 0.5f * std::sin(kPi * ((x % 2) + 0.5f) / 2.0f)
                                      : 0.5f + 0.5f * std::sin(kPi * ((y % 2) + 0.5f) / 2.0f);
            const float n = fbm(uv_of(x, size), uv_of(y, size), 8, seed);
            const float g = 0.7f + 0.2f * thread + 0.1f * n;
            p.set(x, y, glm::vec4(g, g, g, 1.0f));
        }
    }
    return p;
}

Pixels leaf_texture(int size, uint32_t seed) {
    Pixels p(size, size);
    const glm::vec3 background(0.16f, 0.32f, 0.1f);  // leaf-like, so filtering has no halo
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) p.set(x, y, glm::vec4(background, 0.0f));
    }
    const int leaves = 28;
    for (int k = 0; k < leaves; ++k) {
        // Jittered 7x4 grid of leaf centres: even coverage without clumps.
        const float cx =
            (static_cast<float>(k % 7) + 0.2f + 0.6f * hash01(static_cast<uint32_t>(k), 1, seed)) /
            7.0f;
        const float cy =
            (static_cast<float>(k / 7) + 0.2f + 0.6f * hash01(static_cast<uint32_t>(k), 2, seed)) /
            4.0f;
        const float angle = 2.0f * kPi * hash01(static_cast<uint32_t>(k), 3, seed);
        const float len = 0.22f + 0.12f * hash01(static_cast<uint32_t>(k), 4, seed);
        const glm::vec3 colour =
            glm::mix(glm::vec3(0.18f, 0.42f, 0.1f), glm::vec3(0.42f, 0.62f, 0.16f),
                     hash01(static_cast<uint32_t>(k), 5, seed));
        const glm::vec2 axis(std::cos(angle), std::sin(angle));
        for (int y = 0; y < size; ++y) {
            for (int x = 0; x < size; ++x) {
                const glm::vec2 d = glm::vec2(uv_of(x, size) - cx, uv_of(y, size) - cy);
                const float along = glm::dot(d, axis) / len + 0.5f;
                const float across = (d.x * -axis.y + d.y * axis.x) / len;
                if (!inside_leaf(along, across, 0.22f)) continue;
                const float rib = std::abs(across) < 0.012f ? 1.25f : 1.0f;  // midrib
                p.set(x, y, glm::vec4(colour * rib * (0.8f + 0.3f * along), 1.0f));
            }
        }
    }
    return p;
}

namespace {

struct Blade {
    float root, height, lean, half_width;  // uv; half_width at the root
    glm::vec3 tint;
};

Blade blade(int k, int blades, int size, uint32_t seed) {
    const auto b = static_cast<uint32_t>(k);
    return {
        (static_cast<float>(k) + hash01(b, 1, seed)) / static_cast<float>(blades),
        0.5f + 0.45f * hash01(b, 2, seed), (hash01(b, 3, seed) - 0.5f) * 0.3f,
        (1.0f + 0.6f * hash01(b, 4, seed)) / static_cast<float>(size),
        glm::mix(glm::vec3(0.2f, 0.45f, 0.1f), glm::vec3(0.45f, 0.65f, 0.2f), hash01(b, 5, seed))};
}

}  // namespace

Pixels grass_texture(int size, uint32_t seed) {
    Pixels p(size, size);
    const glm::vec3 background(0.2f, 0.36f, 0.12f);  // grass-like, so filtering has no halo
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) p.set(x, y, glm::vec4(background, 0.0f));
    const float s = static_cast<float>(size);
    const int blades = size / 4;
    for (int k = 0; k < blades; ++k) {
        const Blade b = blade(k, blades, size, seed);
        for (int y = 0; y < size; ++y) {
            // 0 at the root (the bottom row), 1 at the tip.
            const float t = (1.0f - uv_of(y, size)) / b.height;
            if (t < 0.0f || t > 1.0f) continue;
            const float centre = b.root + b.lean * t * t;
            for (int x = 0; x < size; ++x) {
                float d = std::abs(uv_of(x, size) - centre);
                d = std::min(d, 1.0f - d);  // the texture tiles across
                const float a = std::clamp((b.half_width * (1.0f - t) - d) * s + 0.5f, 0.0f, 1.0f);
                const size_t i = (static_cast<size_t>(y) * size + x) * 4 + 3;
                if (a * 255.0f <= static_cast<float>(p.rgba[i])) continue;
                p.set(x, y, glm::vec4(b.tint * (0.6f + 0.5f * t), a));
            }
        }
    }
    return p;
}

Pixels poster_texture(int size, const glm::vec3& colour, uint32_t seed) {
    Pixels p(size, size);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const float u = uv_of(x, size), v = uv_of(y, size);
            const float edge = std::min(std::min(u, 1.0f - u), std::min(v, 1.0f - v));
            const float alpha = std::clamp((edge - 0.03f) / 0.04f, 0.0f, 1.0f);
            glm::vec3 c = glm::vec3(0.93f, 0.9f, 0.82f);  // paper
            if (edge > 0.1f && v < 0.6f) c = colour;      // picture block
            const float r = glm::length(glm::vec2(u - 0.5f, v - 0.33f));
            if (r < 0.15f) c = glm::vec3(0.95f, 0.85f, 0.3f);  // a sun on the picture
            const bool text = v > 0.68f && v < 0.9f && edge > 0.12f &&
                              static_cast<int>(v * 40.0f) % 2 == 0 &&
                              hash01(static_cast<uint32_t>(u * 12.0f),
                                     static_cast<uint32_t>(v * 40.0f), seed) > 0.2f;
            if (text) c = glm::vec3(0.15f);
            p.set(x, y, glm::vec4(c, alpha));
        }
    }
    return p;
}

Pixels stain_texture(int size, uint32_t seed) {
    Pixels p(size, size);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const float u = uv_of(x, size), v = uv_of(y, size);
            const float r = glm::length(glm::vec2(u - 0.5f, v - 0.5f)) * 2.0f;
            const float edge = 0.75f + 0.25f * fbm(u, v, 5, seed);
            const float alpha = 0.75f * std::clamp((edge - r) / 0.2f, 0.0f, 1.0f);
            p.set(x, y, glm::vec4(0.22f, 0.15f, 0.08f, alpha));
        }
    }
    return p;
}

Pixels alpha_gradient_texture(int size, bool leaf_shape) {
    Pixels p(size, size);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            // Exact ramp: texel x has alpha (x + 0.5) / size, so with linear filtering the
            // cut edge sits at u == alphaCutoff.
            const float u = uv_of(x, size), v = uv_of(y, size);
            float alpha = u;
            if (leaf_shape && !inside_leaf(u, (v - 0.5f) * 2.0f, 0.9f)) alpha = 0.0f;
            // Colour ramp with a dark tick every 0.1 in u so the cut position can be read off.
            glm::vec3 c = glm::mix(glm::vec3(0.9f, 0.55f, 0.1f), glm::vec3(0.2f, 0.7f, 0.2f), u);
            const float prev_u = u - 1.0f / static_cast<float>(size);
            if (static_cast<int>(u * 10.0f) != static_cast<int>(prev_u * 10.0f)) c *= 0.35f;
            p.set(x, y, glm::vec4(c, alpha));
        }
    }
    return p;
}

Pixels checker_texture(int size, int cells, const glm::vec3& a, const glm::vec3& b) {
    Pixels p(size, size);
    const int cell = size / cells;
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            p.set(x, y, glm::vec4(((x / cell) + (y / cell)) % 2 ? a : b, 1.0f));
        }
    }
    return p;
}

}  // namespace ds::scene::builtin
