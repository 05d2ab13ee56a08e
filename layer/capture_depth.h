#pragma once
// After a captured submission: its depth records and EQUAL re-draw counts read back and
// analysed (depth_records.h) into the frame capture's passes.
#include "layer/capture_record.h"
#include "layer/capture_state.h"

namespace ds::layer {

void read_depth_records(FrameCapture& fc, const CaptureResources& res,
                        CountingRecorder& recorder, const SubmissionPlan& plan,
                        CountingRecorder::Bases bases);

}  // namespace ds::layer
