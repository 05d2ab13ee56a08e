#pragma once
// The render passes and draws of a recorded command buffer, read from the layer's copy.
#include <vector>

#include "layer/frames.h"
#include "layer/state.h"

namespace ds::layer {

std::vector<PassSummary> summarize(DeviceData& device, const CommandBufferState& cb);

}  // namespace ds::layer
