#pragma once
// The captured frame's results, as the layer leaves them for `depthscope layer`: capture.json
// (device, application, frame, passes, draws with their counts, pipelines, not_analysed,
// cost), passes/N.bin (a counted pass's pixel counters: width x height x 4 little-endian u32,
// shaded, discarded, rasterized, 0) and shaders/PIPELINE.spv and PIPELINE.measure.spv (each
// instrumented fragment shader and measurement shader, for spirv-val).
#include <string>

#include "layer/capture_state.h"

namespace ds::layer {

void write_capture(DeviceData& d, const FrameCapture& fc, const std::string& out);

}  // namespace ds::layer
