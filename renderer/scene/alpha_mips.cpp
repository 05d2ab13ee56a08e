#include "renderer/scene/alpha_mips.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace ds::scene {
namespace {

// sRGB-encoded byte -> linear light (IEC 61966-2-1), once per byte value.
const std::array<float, 256>& srgb_to_linear_table() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (size_t i = 0; i < t.size(); ++i) {
            const float c = float(i) / 255.0f;
            t[i] = c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
        }
        return t;
    }();
    return table;
}

uint8_t linear_to_srgb_byte(float linear) {
    const float l = std::clamp(linear, 0.0f, 1.0f);
    const float c = l <= 0.0031308f ? l * 12.92f : 1.055f * std::pow(l, 1.0f / 2.4f) - 0.055f;
    return uint8_t(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f));
}

// The MASK test on one alpha byte, in float as the shaders compute it.
bool passes(uint32_t alpha, float cutoff, float factor) {
    return float(alpha) / 255.0f * factor >= cutoff;
}

// Alpha byte `a` scaled by `s`, rounded and clamped to a byte.
uint32_t scaled(uint32_t a, float s) {
    return uint32_t(std::min(255.0f, std::floor(float(a) * s + 0.5f)));
}

using Histogram = std::array<uint64_t, 256>;

Histogram alpha_histogram(const MipImage& level) {
    Histogram h{};
    for (size_t i = 3; i < level.rgba8.size(); i += 4) ++h[level.rgba8[i]];
    return h;
}

// Coverage of a level whose alpha histogram is `h`, after scaling its alpha by `s`.
double scaled_coverage(const Histogram& h, uint64_t texels, float s, float cutoff, float factor) {
    if (texels == 0) return 0.0;
    uint64_t pass = 0;
    for (uint32_t a = 0; a < 256; ++a)
        if (h[a] && passes(scaled(a, s), cutoff, factor)) pass += h[a];
    return double(pass) / double(texels);
}

// The scale whose coverage is closest to `target` (Castaño's bisection): the smallest scale
// that reaches it and the largest that stays below it, whichever lands nearer; 1 when the
// level already has it.
float coverage_scale(const Histogram& h, uint64_t texels, double target, float cutoff,
                     float factor) {
    auto coverage = [&](float s) { return scaled_coverage(h, texels, s, cutoff, factor); };
    if (coverage(1.0f) == target) return 1.0f;
    float lo = 0.0f, hi = 256.0f;  // at 256 every non-zero alpha is 255
    if (coverage(hi) < target) return hi;
    if (coverage(lo) >= target) return lo;
    for (int i = 0; i < 48 && hi - lo > 1e-7f * hi; ++i) {
        const float mid = 0.5f * (lo + hi);
        (coverage(mid) >= target ? hi : lo) = mid;
    }
    return std::abs(coverage(hi) - target) <= std::abs(coverage(lo) - target) ? hi : lo;
}

// A texel's place among equal alphas: a hash of its index, so that the texels one fix-up moves
// are spread over the level rather than its first rows.
uint32_t scatter(uint32_t i) {
    i ^= i >> 16;
    i *= 0x7feb352du;
    i ^= i >> 15;
    i *= 0x846ca68bu;
    return i ^ (i >> 16);
}

// Where whole groups of texels share one alpha (a ramp's columns), no scale lands on the
// target: then the fewest texels nearest the cutoff move just across it, until the level's
// passing texels are round(target x texels).
void match_count(MipImage& level, double target, float cutoff, float factor) {
    const size_t texels = level.rgba8.size() / 4;
    const auto want = int64_t(std::llround(target * double(texels)));
    std::vector<uint32_t> pass, fail;
    for (uint32_t t = 0; t < texels; ++t)
        (passes(level.rgba8[t * 4 + 3], cutoff, factor) ? pass : fail).push_back(t);
    int64_t change = want - int64_t(pass.size());
    if (change == 0) return;
    uint32_t lowest_pass = 255, highest_fail = 0;
    for (uint32_t a = 0; a < 256; ++a) {
        if (passes(a, cutoff, factor))
            lowest_pass = std::min(lowest_pass, a);
        else
            highest_fail = std::max(highest_fail, a);
    }
    std::vector<uint32_t>& from = change > 0 ? fail : pass;
    const auto alpha = [&](uint32_t t) { return level.rgba8[t * 4 + 3]; };
    const auto nearer = [&](uint32_t a, uint32_t b) {  // nearer the cutoff first
        if (alpha(a) != alpha(b)) return change > 0 ? alpha(a) > alpha(b) : alpha(a) < alpha(b);
        return scatter(a) < scatter(b);
    };
    const size_t n = std::min<size_t>(size_t(std::llabs(change)), from.size());
    std::partial_sort(from.begin(), from.begin() + long(n), from.end(), nearer);
    for (size_t i = 0; i < n; ++i)
        level.rgba8[from[i] * 4 + 3] = uint8_t(change > 0 ? lowest_pass : highest_fail);
}

}  // namespace

uint32_t mip_chain_length(uint32_t width, uint32_t height) {
    uint32_t levels = 1;
    for (uint32_t size = std::max(width, height); size > 1; size /= 2) ++levels;
    return levels;
}

MipImage downsample_rgba8(const MipImage& src, bool srgb) {
    const uint32_t width = src.width, height = src.height;
    MipImage out{std::max(width / 2, 1u), std::max(height / 2, 1u), {}};
    out.rgba8.resize(size_t(out.width) * out.height * 4);
    const std::array<float, 256>& linear = srgb_to_linear_table();
    const uint8_t* s = src.rgba8.data();
    for (uint32_t y = 0; y < out.height; ++y) {
        for (uint32_t x = 0; x < out.width; ++x) {
            // Floor halving leaves an odd last row/column out; a side of 1 is read twice.
            const uint32_t x0 = std::min(2 * x, width - 1), x1 = std::min(2 * x + 1, width - 1);
            const uint32_t y0 = std::min(2 * y, height - 1), y1 = std::min(2 * y + 1, height - 1);
            const size_t t[4] = {(size_t(y0) * width + x0) * 4, (size_t(y0) * width + x1) * 4,
                                 (size_t(y1) * width + x0) * 4, (size_t(y1) * width + x1) * 4};
            uint8_t* o = &out.rgba8[(size_t(y) * out.width + x) * 4];
            for (uint32_t c = 0; c < 4; ++c) {
                if (srgb && c < 3) {
                    const float sum = linear[s[t[0] + c]] + linear[s[t[1] + c]] +
                                      linear[s[t[2] + c]] + linear[s[t[3] + c]];
                    o[c] = linear_to_srgb_byte(sum * 0.25f);
                } else {
                    const uint32_t sum = s[t[0] + c] + s[t[1] + c] + s[t[2] + c] + s[t[3] + c];
                    o[c] = uint8_t((sum + 2) / 4);
                }
            }
        }
    }
    return out;
}

std::vector<MipImage> box_mip_chain(uint32_t width, uint32_t height, std::span<const uint8_t> rgba8,
                                    bool srgb) {
    std::vector<MipImage> chain;
    const uint32_t levels = mip_chain_length(width, height);
    chain.reserve(levels);
    chain.push_back({width, height, std::vector<uint8_t>(rgba8.begin(), rgba8.end())});
    for (uint32_t i = 1; i < levels; ++i) chain.push_back(downsample_rgba8(chain.back(), srgb));
    return chain;
}

double alpha_coverage(const MipImage& level, float cutoff, float factor) {
    const uint64_t texels = level.rgba8.size() / 4;
    return scaled_coverage(alpha_histogram(level), texels, 1.0f, cutoff, factor);
}

std::vector<float> preserve_alpha_coverage(std::vector<MipImage>& chain, float cutoff,
                                           float factor) {
    std::vector<float> scales(chain.size(), 1.0f);
    if (chain.empty()) return scales;
    const double target = alpha_coverage(chain[0], cutoff, factor);
    for (size_t i = 1; i < chain.size(); ++i) {
        MipImage& level = chain[i];
        const float s =
            coverage_scale(alpha_histogram(level), level.rgba8.size() / 4, target, cutoff, factor);
        scales[i] = s;
        if (s != 1.0f)
            for (size_t t = 3; t < level.rgba8.size(); t += 4)
                level.rgba8[t] = uint8_t(scaled(level.rgba8[t], s));
        match_count(level, target, cutoff, factor);
    }
    return scales;
}

std::vector<LevelCoverage> chain_coverage(std::span<const MipImage> chain, float cutoff,
                                          float factor) {
    std::vector<LevelCoverage> out;
    for (size_t i = 0; i < chain.size(); ++i) {
        const double c = alpha_coverage(chain[i], cutoff, factor);
        const double base = out.empty() ? c : out.front().coverage;
        out.push_back(
            {uint32_t(i), chain[i].width, chain[i].height, c, base > 0.0 ? c / base : 1.0});
    }
    return out;
}

}  // namespace ds::scene
