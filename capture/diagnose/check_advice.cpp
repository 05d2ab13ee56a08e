// The prepass advisor (capture/advice.h: frames with the prepass and without) as a finding:
// OVERDRAW when its verdict keeps the prepass (magnitude: the overdraw forward has without
// it), PREPASS_COST when it drops it (magnitude: what the prepass costs). A warning where the
// user's prepass setting goes against the verdict (wasted work), info where it agrees.
// Pixels: where forward's geometry is more than one layer deep (forward_rasterized >= 2).
#include <cmath>
#include <cstdio>

#include "capture/diagnose/checks.h"
#include "capture/diagnose/finding_json.h"
#include "renderer/settings/frame_knobs.h"

namespace ds::diagnose {
namespace {

std::string ms_text(double ms) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f ms", std::fabs(ms));
    return text;
}

std::vector<uint32_t> layered_pixels(const FrameResult& frame) {
    std::vector<uint32_t> out;
    const InspectedImage* image = frame.image("forward_rasterized");
    if (!image) return out;
    const size_t n = size_t(image->width) * image->height;
    for (size_t i = 0; i < n && i * 4 < image->texels.size(); ++i)
        if (image->texels[i * 4] >= 1.5f) out.push_back(uint32_t(i));
    return out;
}

Finding advice_finding(const CheckInput& in, const capture::Advice& a) {
    const bool prepass = knob_value(in.settings, knobs::kPrepass);
    Finding f;
    f.detector = "advisor";
    const std::string overdraw = "overdraw " + grouped(std::round(a.overdraw * 100) / 100) + " (" +
                                 grouped(double(a.input.without.forward_shaded)) +
                                 " fragments forward shades without the prepass for " +
                                 grouped(double(a.input.without.covered_pixels)) + " px)";
    if (a.keep) {
        f.code = "OVERDRAW";
        f.severity = prepass ? Severity::Info : Severity::Warning;
        f.magnitude = {a.overdraw, "x"};
        f.message = overdraw + ": keep the prepass: it saves " + ms_text(a.measured_change_ms) +
                    " (predicted " + ms_text(a.predicted_change_ms) + ")";
        f.fix = prepass ? "keep prepass=on" : "prepass=on";
    } else {
        f.code = "PREPASS_COST";
        f.severity = prepass ? Severity::Warning : Severity::Info;
        f.magnitude = {a.measured_change_ms, "ms"};
        f.message = "the prepass costs " + ms_text(a.measured_change_ms) + " and pays back less; " +
                    overdraw;
        f.fix =
            prepass ? "prepass=off (or prepass_mode=depth: a cheaper prepass)" : "keep prepass=off";
    }
    f.message += prepass ? " (prepass=on)" : " (prepass=off)";
    f.pixels = layered_pixels(in.measured);
    return f;
}

}  // namespace

void check_advice(const CheckInput& in, CheckOutput& out) {
    if (!in.advice) {
        out.skip("advisor", in.advice_skipped.empty() ? "not run" : in.advice_skipped);
        return;
    }
    out.ran.push_back("advisor");
    out.findings.push_back(advice_finding(in, *in.advice));
}

}  // namespace ds::diagnose
