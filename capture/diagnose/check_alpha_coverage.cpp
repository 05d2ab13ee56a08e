// Alpha coverage of masked materials (issue 24 lists it "when it exists"): there is no such
// measurement yet, so the detector is always listed as skipped, with the reason.
#include "capture/diagnose/checks.h"

namespace ds::diagnose {

void check_alpha_coverage(const CheckInput& in, CheckOutput& out) {
    bool masked = false;
    for (const scene::Material& m : in.scene.materials)
        masked = masked || m.alpha_mode == scene::AlphaMode::Mask;
    out.skip("alpha_coverage", masked ? "no alpha coverage measurement exists in depthscope yet"
                                      : "the scene has no MASK materials");
}

}  // namespace ds::diagnose
