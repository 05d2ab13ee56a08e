#include "capture/tune/score.h"

#include "renderer/metrics/luma.h"
#include "renderer/metrics/ssim.h"
#include "renderer/metrics/threshold.h"

namespace ds::tune {

ImageScore score_against(const std::vector<uint8_t>& rgba8, const Reference& ref) {
    const metrics::Rgba8View frame{ref.width, ref.height, rgba8};
    const metrics::Rgba8View truth{ref.width, ref.height, ref.rgba8};
    metrics::require_same_size("tune", frame, truth);
    const metrics::LumaImage a = metrics::luma(frame), b = metrics::luma(truth);
    ImageScore s;
    s.ssim = metrics::ssim(a, b).mean;
    s.percent_over = metrics::pixels_over_threshold(frame, truth, kScoreThreshold).percent();
    if (!ref.edges.empty()) {
        const std::vector<bool> mask(ref.edges.begin(), ref.edges.end());
        const metrics::MaskedError e = metrics::edge_error(a, b, mask);
        s.edge_pixels = e.pixels;
        s.edge_error = e.pixels ? e.mean : 0.0;
    }
    return s;
}

}  // namespace ds::tune
