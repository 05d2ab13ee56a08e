// SSIM (renderer/metrics/ssim.h) against scikit-image's structural_similarity on deterministic
// image pairs written as PNGs (Debian's python3-skimage, run by /usr/bin/python3: a python3
// earlier on PATH may lack it), and its edge cases.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "renderer/common/error.h"
#include "renderer/metrics/luma.h"
#include "renderer/metrics/ssim.h"

#include <stb/stb_image_write.h>  // Debian's libstb

namespace fs = std::filesystem;

namespace ds::metrics {
namespace {

struct Rgba {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> bytes;
    Rgba8View view() const { return {width, height, bytes}; }
};

// A small deterministic generator (the same bytes on every platform).
class Lcg {
  public:
    explicit Lcg(uint32_t seed) : state_(seed) {}
    uint8_t next() {
        state_ = state_ * 1664525u + 1013904223u;
        return uint8_t(state_ >> 24);
    }

  private:
    uint32_t state_;
};

Rgba make(uint32_t w, uint32_t h, const std::function<std::array<int, 3>(uint32_t, uint32_t)>& f) {
    Rgba out{w, h, std::vector<uint8_t>(size_t(w) * h * 4, 255)};
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const std::array<int, 3> c = f(x, y);
            for (size_t i = 0; i < 3; ++i)
                out.bytes[(size_t(y) * w + x) * 4 + i] = uint8_t(std::clamp(c[i], 0, 255));
        }
    return out;
}

Rgba noise(uint32_t w, uint32_t h, uint32_t seed, int offset) {
    Lcg lcg(seed);
    return make(w, h, [&](uint32_t, uint32_t) {
        return std::array<int, 3>{lcg.next() + offset, lcg.next() + offset, lcg.next() + offset};
    });
}

std::array<int, 3> gradient_at(uint32_t x, uint32_t y) {
    return {int(x * 7), int(y * 11), int((x + y) * 4)};
}

// The gradient blurred by a 3x3 box (clamped at the edges) and quantised to steps of 16.
Rgba blurred_quantised_gradient(uint32_t w, uint32_t h) {
    return make(w, h, [&](uint32_t x, uint32_t y) {
        std::array<int, 3> sum{}, n{};
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const int sx = std::clamp(int(x) + dx, 0, int(w) - 1);
                const int sy = std::clamp(int(y) + dy, 0, int(h) - 1);
                const std::array<int, 3> c = gradient_at(uint32_t(sx), uint32_t(sy));
                for (size_t i = 0; i < 3; ++i) sum[i] += std::min(c[i], 255), n[i] += 1;
            }
        std::array<int, 3> out{};
        for (size_t i = 0; i < 3; ++i) out[i] = (sum[i] / n[i]) / 16 * 16;
        return out;
    });
}

Rgba checkerboard(uint32_t w, uint32_t h, uint32_t cell, uint32_t shift) {
    return make(w, h, [&](uint32_t x, uint32_t y) {
        const int v = ((x + shift) / cell + y / cell) % 2 ? 220 : 30;
        return std::array<int, 3>{v, v / 2, 255 - v};
    });
}

struct Reference {
    double mean = 0;
    std::vector<double> map;
};

// ssim_reference.py (skimage) on the two images, through PNG files.
Reference skimage_ssim(const Rgba& a, const Rgba& b, const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("ds-metrics-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path pa = dir / (name + "-a.png"), pb = dir / (name + "-b.png");
    const fs::path map = dir / (name + ".f64");
    for (const auto& [path, image] : {std::pair{pa, &a}, std::pair{pb, &b}})
        EXPECT_TRUE(stbi_write_png(path.c_str(), int(image->width), int(image->height), 4,
                                   image->bytes.data(), int(image->width * 4)));
    const std::string command = std::string("/usr/bin/python3 ") + DS_SSIM_REFERENCE + " " +
                                pa.string() + " " + pb.string() + " " + map.string() + " 2>&1";
    std::string out;
    if (FILE* pipe = ::popen(command.c_str(), "r")) {
        char buffer[256];
        while (std::fgets(buffer, sizeof buffer, pipe)) out += buffer;
        EXPECT_EQ(::pclose(pipe), 0) << command << "\n" << out;
    }
    Reference r;
    r.mean = std::strtod(out.c_str(), nullptr);
    r.map.resize(size_t(a.width) * a.height);
    std::ifstream(map, std::ios::binary)
        .read(reinterpret_cast<char*>(r.map.data()), std::streamsize(r.map.size() * 8));
    fs::remove_all(dir);
    return r;
}

void expect_as_skimage(const Rgba& a, const Rgba& b, const std::string& name) {
    const SsimResult ours = ssim(luma(a.view()), luma(b.view()));
    const Reference ref = skimage_ssim(a, b, name);
    double worst = 0;
    for (size_t p = 0; p < ref.map.size(); ++p)
        worst = std::max(worst, std::fabs(ours.map.values[p] - ref.map[p]));
    const double mean_difference = std::fabs(ours.mean - ref.mean);
    std::printf("%s %ux%u: SSIM %.10f, skimage %.10f, |difference| %.3g, map max %.3g\n",
                name.c_str(), a.width, a.height, ours.mean, ref.mean, mean_difference, worst);
    EXPECT_LT(mean_difference, 1e-4) << name;
    EXPECT_LT(worst, 1e-4) << name;
    EXPECT_LT(ours.mean, 1.0) << name;  // every pair differs
}

TEST(Ssim, AgreesWithScikitImage) {
    expect_as_skimage(noise(64, 48, 1, 0), noise(64, 48, 1, 20), "noise-offset");
    expect_as_skimage(make(37, 23, gradient_at), blurred_quantised_gradient(37, 23),
                      "gradient-blurred");
    expect_as_skimage(checkerboard(40, 40, 4, 0), checkerboard(40, 40, 4, 1), "checker-shifted");
    expect_as_skimage(noise(11, 11, 7, 0), noise(11, 11, 8, 0), "noise-11x11");
    expect_as_skimage(make(13, 29,
                           [](uint32_t, uint32_t) {
                               return std::array<int, 3>{90, 90, 90};
                           }),
                      make(13, 29,
                           [](uint32_t, uint32_t) {
                               return std::array<int, 3>{99, 90, 90};
                           }),
                      "flat");
}

TEST(Ssim, IdenticalImagesGiveOne) {
    const LumaImage a = luma(noise(37, 23, 3, 0).view());
    const SsimResult r = ssim(a, a);
    EXPECT_DOUBLE_EQ(r.mean, 1.0);
    ASSERT_EQ(r.map.values.size(), size_t(37 * 23));
    for (const double s : r.map.values) EXPECT_DOUBLE_EQ(s, 1.0);
}

TEST(Ssim, RefusesSmallImagesAndDifferentSizes) {
    const auto message = [](const LumaImage& a, const LumaImage& b) {
        try {
            ssim(a, b);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const LumaImage narrow = luma(noise(10, 40, 1, 0).view());
    EXPECT_EQ(message(narrow, narrow), "SSIM: a 10x40 image is under 11 pixels on a side");
    const LumaImage low = luma(noise(40, 10, 1, 0).view());
    EXPECT_EQ(message(low, low), "SSIM: a 40x10 image is under 11 pixels on a side");
    EXPECT_EQ(message(luma(noise(11, 12, 1, 0).view()), luma(noise(12, 11, 1, 0).view())),
              "SSIM: images of different sizes (11x12 and 12x11)");
}

}  // namespace
}  // namespace ds::metrics
