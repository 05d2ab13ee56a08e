// DEPTH_PRECISION (info): the depth_precision pass's per-pixel step (one representable depth
// value, along the view ray, in scene units) against the distance of what the pixel shows:
// pixels whose step is coarser than kRelativeStep of their distance, when they are more than
// kShareOfCovered of the covered pixels. The message gives the scene's visible range against
// the planes, since the near plane sets the precision of unorm and forward-Z depth.
#include <algorithm>
#include <cstdio>

#include "capture/diagnose/checks.h"
#include "capture/diagnose/finding_json.h"
#include "renderer/settings/frame_knobs.h"

namespace ds::diagnose {
namespace {

constexpr double kRelativeStep = 1e-4;     // one step coarser than 1/10,000 of the distance
constexpr double kShareOfCovered = 0.001;  // of the covered pixels

std::string g3(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", v);
    return text;
}

struct PrecisionScan {
    std::vector<uint32_t> coarse;  // pixels over the threshold
    uint64_t covered = 0;
    double worst_step = 0, worst_at = 0;
    double nearest = 0, farthest = 0;  // visible range along the rays
};

PrecisionScan scan_precision(const InspectedImage& image) {
    PrecisionScan s;
    const size_t n = size_t(image.width) * image.height;
    for (size_t i = 0; i < n && i * 4 + 1 < image.texels.size(); ++i) {
        const double step = image.texels[i * 4], distance = image.texels[i * 4 + 1];
        if (!(distance > 0)) continue;  // sky
        s.nearest = s.covered ? std::min(s.nearest, distance) : distance;
        s.farthest = std::max(s.farthest, distance);
        ++s.covered;
        if (step < kRelativeStep * distance) continue;
        s.coarse.push_back(uint32_t(i));
        if (step / distance > s.worst_step / std::max(s.worst_at, 1e-30)) {
            s.worst_step = step;
            s.worst_at = distance;
        }
    }
    return s;
}

Finding precision_finding(const CheckInput& in, PrecisionScan s) {
    Finding f;
    f.code = "DEPTH_PRECISION";
    f.severity = Severity::Info;
    f.detector = "depth_precision";
    f.magnitude = {double(s.coarse.size()), "px"};
    float znear = 0, zfar = 0;
    if (in.measured.depth) {
        znear = in.measured.depth->znear;
        zfar = in.measured.depth->zfar;
    }
    f.message = "depth precision: " + grouped(double(s.coarse.size())) +
                " px have a depth step coarser than 1/10,000 of their distance (worst " +
                g3(s.worst_step) + " at " + g3(s.worst_at) + "; " + depth_label(in.settings) +
                ", planes " + g3(znear) + ".." + g3(zfar) + ", visible " + g3(s.nearest) + ".." +
                g3(s.farthest) + ")";
    f.fix =
        "depth_format=d32f with reverse_z=on keeps the step proportional to the distance; "
        "or raise znear towards the nearest visible surface (" +
        g3(s.nearest) + ")";
    f.pixels = std::move(s.coarse);
    return f;
}

}  // namespace

void check_precision(const CheckInput& in, CheckOutput& out) {
    const InspectedImage* image = in.measured.image("depth_precision");
    if (!image) {
        out.skip("depth_precision",
                 frame_skip_reason(in.measured, "depth_precision", "depth_precision")
                     .value_or(knob_value(in.settings, knobs::kPrepass)
                                   ? "not run"
                                   : "prepass off: it reads the prepass depth"));
        return;
    }
    out.ran.push_back("depth_precision");
    PrecisionScan s = scan_precision(*image);
    if (s.covered > 0 && double(s.coarse.size()) > kShareOfCovered * double(s.covered))
        out.findings.push_back(precision_finding(in, std::move(s)));
}

}  // namespace ds::diagnose
