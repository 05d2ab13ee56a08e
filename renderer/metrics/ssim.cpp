#include "renderer/metrics/ssim.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "renderer/common/error.h"

namespace ds::metrics {
namespace {

constexpr double kSigma = 1.5;
constexpr double kTruncate = 3.5;
constexpr int kRadius = int(kTruncate * kSigma + 0.5);  // 5, as ndimage rounds it
static_assert(2 * kRadius + 1 == int(kSsimWindow));
constexpr double kDataRange = 255;
constexpr double kC1 = (0.01 * kDataRange) * (0.01 * kDataRange);
constexpr double kC2 = (0.03 * kDataRange) * (0.03 * kDataRange);

// weights[k] for the tap at distance k from the centre (k = 0..kRadius): exp(-x^2 / (2 sigma^2))
// normalised over all 11 taps.
std::array<double, kRadius + 1> ssim_taps() {
    std::array<double, 2 * kRadius + 1> all{};
    double sum = 0;
    for (int x = -kRadius; x <= kRadius; ++x) {
        all[size_t(x + kRadius)] = std::exp(-0.5 / (kSigma * kSigma) * double(x * x));
        sum += all[size_t(x + kRadius)];
    }
    std::array<double, kRadius + 1> taps{};
    for (int k = 0; k <= kRadius; ++k) taps[size_t(k)] = all[size_t(k + kRadius)] / sum;
    return taps;
}

// scipy's 'reflect': the index `i` of a line of `n` values mirrored about its edges (period 2n).
size_t reflected(int64_t i, int64_t n) {
    const int64_t period = 2 * n;
    int64_t m = i % period;
    if (m < 0) m += period;
    return size_t(m < n ? m : period - 1 - m);
}

using Taps = std::array<double, kRadius + 1>;

// One line: out = centre * w0, then (left + right) * wk from the farthest tap in (the order of
// ndimage's correlate1d for a symmetric kernel). `line` holds kRadius padded values each side.
void filter_line(const double* line, size_t n, const Taps& w, double* out, size_t out_stride) {
    for (size_t i = 0; i < n; ++i) {
        const double* c = line + kRadius + i;
        double v = c[0] * w[0];
        for (int k = kRadius; k >= 1; --k) v += (c[-k] + c[k]) * w[size_t(k)];
        out[i * out_stride] = v;
    }
}

// gaussian_filter of one image: along axis 0 (down each column), then along axis 1 (each row).
std::vector<double> gaussian(const std::vector<double>& in, uint32_t width, uint32_t height,
                             const Taps& w) {
    std::vector<double> columns(in.size()), out(in.size());
    std::vector<double> line(std::max(width, height) + 2 * kRadius);
    for (uint32_t x = 0; x < width; ++x) {
        for (int64_t i = -kRadius; i < int64_t(height) + kRadius; ++i)
            line[size_t(i + kRadius)] = in[reflected(i, height) * width + x];
        filter_line(line.data(), height, w, &columns[x], width);
    }
    for (uint32_t y = 0; y < height; ++y) {
        const double* row = &columns[size_t(y) * width];
        for (int64_t i = -kRadius; i < int64_t(width) + kRadius; ++i)
            line[size_t(i + kRadius)] = row[reflected(i, width)];
        filter_line(line.data(), width, w, &out[size_t(y) * width], 1);
    }
    return out;
}

std::vector<double> product(const std::vector<double>& a, const std::vector<double>& b) {
    std::vector<double> out(a.size());
    for (size_t i = 0; i < a.size(); ++i) out[i] = a[i] * b[i];
    return out;
}

void check_ssim_input(const LumaImage& a, const LumaImage& b) {
    require_same_size("SSIM", a, b);
    if (a.width < kSsimWindow || a.height < kSsimWindow)
        throw Error("SSIM: a " + size_text(a.width, a.height) + " image is under " +
                    std::to_string(kSsimWindow) + " pixels on a side");
}

}  // namespace

SsimResult ssim(const LumaImage& a, const LumaImage& b) {
    check_ssim_input(a, b);
    const uint32_t w = a.width, h = a.height;
    const Taps taps = ssim_taps();
    const std::vector<double> ux = gaussian(a.values, w, h, taps);
    const std::vector<double> uy = gaussian(b.values, w, h, taps);
    const std::vector<double> uxx = gaussian(product(a.values, a.values), w, h, taps);
    const std::vector<double> uyy = gaussian(product(b.values, b.values), w, h, taps);
    const std::vector<double> uxy = gaussian(product(a.values, b.values), w, h, taps);

    SsimResult out{0, {w, h, std::vector<double>(a.values.size())}};
    for (size_t p = 0; p < ux.size(); ++p) {
        const double vx = uxx[p] - ux[p] * ux[p];
        const double vy = uyy[p] - uy[p] * uy[p];
        const double vxy = uxy[p] - ux[p] * uy[p];
        const double a1 = 2 * ux[p] * uy[p] + kC1, a2 = 2 * vxy + kC2;
        const double b1 = ux[p] * ux[p] + uy[p] * uy[p] + kC1, b2 = vx + vy + kC2;
        out.map.values[p] = (a1 * a2) / (b1 * b2);
    }
    double sum = 0;
    for (uint32_t y = kRadius; y < h - kRadius; ++y)
        for (uint32_t x = kRadius; x < w - kRadius; ++x) sum += out.map.at(x, y);
    out.mean = sum / (double(w - 2 * kRadius) * double(h - 2 * kRadius));
    return out;
}

}  // namespace ds::metrics
