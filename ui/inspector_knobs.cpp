#include "ui/inspector_knobs.h"

namespace ds::ui {

const Knob<float> kRenderScale{"render_scale"};
const Knob<float> kMotionScale{"motion_scale"};
const Knob<bool> kContinuous{"continuous"};

namespace {

std::vector<SettingDef> inspector_knobs() {
    using I = Invalidates;
    return {
        float_knob(kRenderScale, "camera", "1", 0.25, 2,
                   "inspector: the frame renders at the viewer's size times this (below 1 keeps "
                   "a CPU device interactive); capture and bench render at --size",
                   I::Resources),
        float_knob(kMotionScale, "camera", "0.5", 0.1, 1,
                   "inspector: while the camera moves, frames render at this times the render "
                   "size, and at the full size once it stops",
                   I::Nothing),
        bool_knob(kContinuous, "camera", false,
                  "inspector: render a scene frame every UI frame (for the timing history); "
                  "off: only when something that affects the frame changed",
                  I::Nothing),
    };
}

}  // namespace

// Registered with the registry; this file is linked wherever the inspector reads its knobs.
const KnobSource kInspectorKnobs(KnobOwner::Inspector, &inspector_knobs);

}  // namespace ds::ui
