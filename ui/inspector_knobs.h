#pragma once
// The inspector's knobs (how it drives frames), declared in inspector_knobs.cpp. The handles
// are defined there too, so that every reader links the file that registers them.
#include "renderer/settings/knob.h"

namespace ds::ui {

extern const Knob<float> kRenderScale;
extern const Knob<float> kMotionScale;
extern const Knob<bool> kContinuous;

}  // namespace ds::ui
