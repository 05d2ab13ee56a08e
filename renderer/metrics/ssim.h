#pragma once
// SSIM (Wang, Bovik, Sheikh, Simoncelli 2004) computed as scikit-image 0.19 computes
// structural_similarity(a, b, gaussian_weights=True, sigma=1.5, use_sample_covariance=False,
// data_range=255) on one-channel images — tests/unit/metrics checks it against Debian's
// python3-skimage:
//  - local means, variances and the covariance through a Gaussian window, sigma 1.5, truncated
//    at 3.5 sigma (11 taps, weights normalised to sum 1), applied as scipy.ndimage's
//    gaussian_filter: rows of taps down the columns first, then along the rows, each edge
//    padded as scipy's 'reflect' (half-sample symmetric: d c b a | a b c d);
//  - population (co)variances; C1 = (0.01 * 255)^2, C2 = (0.03 * 255)^2;
//  - S = (2 ux uy + C1)(2 vxy + C2) / ((ux^2 + uy^2 + C1)(vx + vy + C2)) per pixel, and the
//    mean of S over the image less a 5-pixel border (the window's radius, skimage's crop).
// Double precision throughout.
#include <cstdint>

#include "renderer/metrics/image.h"

namespace ds::metrics {

// The window's side: images must be at least this many pixels on each side.
inline constexpr uint32_t kSsimWindow = 11;

struct SsimResult {
    double mean = 0;  // the SSIM index: mean of `map` inside the 5-pixel border
    LumaImage map;    // S per pixel, full size (the border included, as skimage's full=True)
};

// Throws ds::Error (one line) for images of different sizes or under kSsimWindow pixels on a
// side; callers taking images from the command line turn it into a usage error.
SsimResult ssim(const LumaImage& a, const LumaImage& b);

}  // namespace ds::metrics
