// DEPTH_RANGE (warning): a view whose near/far planes leave fewer than
// Thresholds::min_steps_per_unit representable depths per scene unit at the far end (the
// coarsest step between the planes, lint_depth.cpp), in the user's depth format: surfaces
// closer than one step there cannot be told apart. Per view
// (cameras have their own planes); views with the same planes are reported once.
#include <algorithm>

#include "capture/lint/checks.h"

namespace ds::lint {
namespace {

Finding range_finding(const View& v, const view::DepthConfig& c, double steps, double min_steps) {
    Finding f;
    f.code = "DEPTH_RANGE";
    f.severity = Severity::Warning;
    f.detector = "depth_range";
    f.pointer = v.pointer;
    f.magnitude = {steps, "steps per scene unit"};
    f.message = "depth range of " + v.name + ": planes " + g3(c.znear) + ".." + g3(c.zfar) +
                " (far/near " + g3(c.zfar / c.znear) + ") in " + depth_name(c) + " leave " +
                g3(steps) + " depth steps per scene unit at the far end (one step " +
                g3(coarsest_step(c)) + "), fewer than " + g3(min_steps);
    for (const view::DepthConfig& other : every_format(c))
        if (depth_name(other) != depth_name(c))
            f.message += "; " + depth_name(other) + ": " + g3(1.0 / coarsest_step(other));
    f.fix =
        "raise znear towards the nearest surface, lower zfar, or depth_format=d32f with "
        "reverse_z=on (steps proportional to the distance)";
    return f;
}

}  // namespace

void check_depth_range(const Input& in, Output& out) {
    out.ran.push_back("depth_range");
    std::vector<std::pair<double, double>> seen;
    for (const View& v : in.views) {
        const view::DepthConfig c = depth_config(in.settings, v.camera);
        const std::pair planes{c.znear, c.zfar};
        if (std::find(seen.begin(), seen.end(), planes) != seen.end()) continue;
        seen.push_back(planes);
        const double steps = 1.0 / coarsest_step(c);
        if (steps < in.thresholds.min_steps_per_unit)
            out.findings.push_back(range_finding(v, c, steps, in.thresholds.min_steps_per_unit));
    }
}

}  // namespace ds::lint
