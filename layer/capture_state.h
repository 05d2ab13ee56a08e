#pragma once
// What the chosen frame's capture has gathered so far (capture.h).
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "layer/capture_pipelines.h"
#include "layer/capture_record.h"
#include "layer/capture_resources.h"

namespace ds::layer {

struct CapturedPass {
    PassSummary summary;
    bool counted = false;
    uint32_t submission = 0;
    std::vector<uint32_t> pixels;  // width x height x 4 (shaded, discarded, rasterized, 0)
    uint32_t pixel_width = 0, pixel_height = 0;
    std::optional<DepthPassAnalysis> zfight;  // a pass with depth records
    std::optional<EqualCheckResult> equal;    // a pass with EQUAL re-draws
};

struct CapturedDrawResult {
    CapturedDraw draw;  // draw.pass: index into FrameCapture::passes
    DrawCounters counts{};
    uint64_t samples_passed = 0;
};

struct FrameCapture {
    explicit FrameCapture(DeviceData& d) : pipelines(d) {}
    CountingPipelines pipelines;
    std::map<uint32_t, VkCommandPool> pools;  // by queue family
    std::vector<CapturedPass> passes;
    std::vector<CapturedDrawResult> draws;
    std::vector<std::string> not_analysed;
    std::vector<std::string> labels;  // debug-utils labels open across command buffers
    uint32_t submissions = 0;
    std::vector<DepthWritingPass> depth_passes;       // for the EQUAL check's matching
    std::map<uint32_t, PrepassWinners> winners;       // by frame pass, with depth records
    double capture_ms = 0;           // the layer's extra time in the captured frame
    VkDeviceSize counter_bytes = 0;  // the largest submission's counters
    VkDeviceSize depth_record_bytes = 0;  // of which the depth records (zfight, equal_check)
};

}  // namespace ds::layer
