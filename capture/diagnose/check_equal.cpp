// EQUAL_HOLES (error) and EQUAL_TIES (warning), from the equal_check pass (prepass on,
// depth_compare=equal, msaa 1): holes are pixels the prepass covered that forward did not
// shade (the background shows through), ties pixels forward shaded more than once (coplanar
// surfaces both pass EQUAL: shaded twice, the last one kept). Pixels from its image (1 hole,
// 2 tie); surfaces: the prepass winners it names (its top ten).
#include "capture/diagnose/checks.h"
#include "capture/diagnose/finding_json.h"
#include "renderer/passes/equal_check.h"
#include "renderer/passes/forward.h"

namespace ds::diagnose {
namespace {

constexpr float kHoleMark = 1.0f, kTieMark = 2.0f;

Finding equal_finding(const CheckInput& in, const EqualCheckResult& r, bool holes) {
    Finding f;
    f.detector = "equal_check";
    for (const EqualCheckSurface& s : r.surfaces)
        if ((holes ? s.holes : s.multiple) > 0)
            f.surfaces.push_back(surface_named(in.scene, s.name));
    if (!f.surfaces.empty()) f.pointer = f.surfaces.front().pointer;
    if (const InspectedImage* image = in.measured.image("equal_check"))
        f.pixels = pixels_where(*image, holes ? kHoleMark : kTieMark);
    return f;
}

Finding holes_finding(const CheckInput& in, const EqualCheckResult& r) {
    Finding f = equal_finding(in, r, true);
    f.code = "EQUAL_HOLES";
    f.severity = Severity::Error;
    f.magnitude = {double(r.holes), "px"};
    const bool invariant = knob_value(in.settings, passes::ForwardPass::kInvariant);
    f.message = "EQUAL holes: " + grouped(double(r.holes)) + " px: " +
                (invariant ? "forward's depth differs from the prepass's (its vertex stage, "
                             "jitter or alpha cutoff is not the prepass's)"
                           : "gl_Position is not invariant (invariant=off)");
    f.fix = invariant ? "make both vertex stages compute gl_Position bit-identically (invariant "
                        "gl_Position, the same expression, inputs and jitter), or "
                        "depth_compare=greater_or_equal"
                      : "invariant=on: forward's gl_Position must be computed exactly as the "
                        "prepass's (invariant gl_Position, the same expression)";
    return f;
}

Finding ties_finding(const CheckInput& in, const EqualCheckResult& r) {
    Finding f = equal_finding(in, r, false);
    f.code = "EQUAL_TIES";
    f.severity = Severity::Warning;
    f.magnitude = {double(r.multiple), "px"};
    f.message = "EQUAL ties: " + grouped(double(r.multiple)) +
                " px shaded more than once by forward (coplanar surfaces both pass EQUAL)";
    f.fix = "draw coplanar overlays as decals (decal_pass=on) and remove duplicated surfaces";
    return f;
}

}  // namespace

void check_equal(const CheckInput& in, CheckOutput& out) {
    const EqualCheckResult* r = in.measured.find<EqualCheckResult>();
    if (!r) {
        out.skip("equal_check",
                 frame_skip_reason(in.measured, "equal_check", "equal_check").value_or("not run"));
        return;
    }
    out.ran.push_back("equal_check");
    if (r->holes > 0) out.findings.push_back(holes_finding(in, *r));
    if (r->multiple > 0) out.findings.push_back(ties_finding(in, *r));
}

}  // namespace ds::diagnose
