#pragma once
// A frame scored against the reference (reference.h) with the image metrics of
// renderer/metrics: SSIM on luma, the mean luma error over the reference's edge pixels, and
// diff's % of pixels over a threshold.
#include <cstdint>
#include <vector>

#include "capture/tune/reference.h"

namespace ds::tune {

struct ImageScore {
    double ssim = 0;
    double edge_error = 0;     // mean |luma difference| (of 255) over the edge pixels
    uint64_t edge_pixels = 0;  // 0: the reference has no surface ids (edge_error is 0)
    double percent_over = 0;   // % of pixels whose largest channel differs by >= threshold
    // What tuning minimises: the edge error where there are edges, else 1 - SSIM.
    double error() const { return edge_pixels ? edge_error : 1.0 - ssim; }
};

inline constexpr int kScoreThreshold = 8;  // diff's default, of 255

// `rgba8` must have the reference's size (ds::Error otherwise).
ImageScore score_against(const std::vector<uint8_t>& rgba8, const Reference& ref);

}  // namespace ds::tune
