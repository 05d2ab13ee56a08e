#pragma once
// What a caller asks of one frame (Renderer::render's request): its size, what is read back,
// which images are inspected, and the pixel history or sample view it wants.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ds {

// Benchmarks skip the copy to host memory; WithMsaaDepth is Yes plus MsaaResult's depth.
// Color reads back the final image only (no covered pixels, no MSAA probe: the inspector).
enum class ReadBack { Yes, No, WithMsaaDepth, Color };
// Frames read back in full: the image, covered pixels and (msaa > 1) the sample probe.
inline bool reads_back_fully(ReadBack r) {
    return r == ReadBack::Yes || r == ReadBack::WithMsaaDepth;
}

// Read back one graph image by name at the end of the frame ("final": the tonemapped image;
// any other: a compute pass "inspect" samples it, so it appears last in FrameResult::passes).
struct InspectRequest {
    std::string resource;  // "" = none
    uint32_t sample = 0;   // multisampled images
};

// Pixel history for one pixel of the frame (x, y in pixels, row 0 = top): each geometry pass
// replays its draws with instrumented shaders first (graph role history).
struct PixelQuery {
    uint32_t x = 0, y = 0;
};

// The MSAA sample view: every sample of a rectangle of the frame (pixels, row 0 = top).
struct SampleQuery {
    uint32_t x = 0, y = 0, width = 1, height = 1;
};

struct RenderRequest {
    uint32_t width = 0, height = 0;
    ReadBack read_back = ReadBack::Yes;
    // Images read back: the first is FrameResult::inspected, the others FrameResult::overlays
    // (one dispatch each; "final" only as the first).
    std::vector<InspectRequest> inspect = {};
    std::optional<PixelQuery> pixel = std::nullopt;     // PixelHistory (pixel_history.h)
    std::optional<SampleQuery> samples = std::nullopt;  // MsaaSamples (msaa_samples.h)
};

}  // namespace ds
