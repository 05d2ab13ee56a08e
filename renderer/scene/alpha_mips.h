#pragma once
// Mip chains of RGBA8 images on the CPU and the alpha coverage of their levels (issue 30 part 5;
// Castaño, "Computing Alpha Mipmaps", 2010). Pure: no Vulkan. The one implementation that the
// renderer's uploads (gpu_scene: every level it makes on the CPU), report.json's
// `alpha_coverage` and diagnose's alpha_coverage check use.
//
// Box chain: each level a 2x2 box filter of the one above, sizes halved and floored, never
// below 1 (an odd last row or column is left out; a side of 1 reads its texel twice). An sRGB
// image's colour is averaged in linear light and encoded again, as a GPU's linear blit of an
// _SRGB format does; alpha is always linear.
// Coverage of a level: the fraction of its texels that pass the MASK alpha test, alpha x
// baseColorFactor.a >= cutoff (the shaders discard below the cutoff: common/alpha_test.glsl's
// users), in float as the GPU computes it (byte / 255 x factor).
// Preserve (Castaño): every level >= 1 of a box chain gets its alpha scaled by the factor that
// brings its coverage closest to level 0's, found by bisection; clamped to [0, 255], colour
// unchanged. A level whose box coverage already equals level 0's keeps its alpha.
#include <cstdint>
#include <span>
#include <vector>

namespace ds::scene {

struct MipImage {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba8;  // tightly packed, row 0 first
};

// The number of levels of a full chain down to 1x1 (vk::mip_level_count's count).
uint32_t mip_chain_length(uint32_t width, uint32_t height);

// The level below `src`: max(w / 2, 1) x max(h / 2, 1), a 2x2 box (reads clamped to the edge).
MipImage downsample_rgba8(const MipImage& src, bool srgb);

// Level 0 (a copy of `rgba8`, width x height) and every level below it, down to 1x1.
std::vector<MipImage> box_mip_chain(uint32_t width, uint32_t height, std::span<const uint8_t> rgba8,
                                    bool srgb);

// Fraction of `level`'s texels whose alpha / 255 x factor >= cutoff (0 for an empty level).
double alpha_coverage(const MipImage& level, float cutoff, float factor);

// Scales every level >= 1's alpha so that its coverage matches level 0's (Castaño), each by
// its own factor (bisection); returns those factors (1 for level 0 and kept levels). Where no
// scale lands on it (texels that share one alpha flip together, as a ramp's columns do), the
// fewest texels nearest the cutoff are then moved just across it, so that each level passes
// on round(level 0's coverage x its texels) texels: within one texel of level 0's.
std::vector<float> preserve_alpha_coverage(std::vector<MipImage>& chain, float cutoff,
                                           float factor);

// One level's coverage, and its ratio to level 0's (1 when level 0's is 0).
struct LevelCoverage {
    uint32_t level = 0, width = 0, height = 0;
    double coverage = 0.0;
    double relative = 1.0;
};
std::vector<LevelCoverage> chain_coverage(std::span<const MipImage> chain, float cutoff,
                                          float factor);

}  // namespace ds::scene
