#pragma once
// What a frame gives back: the facts of the whole frame (FrameResult) and, by type, each pass's
// own result (FrameResult::slots: HizResult in passes/hiz.h, ZfightResult in passes/zfight.h,
// ...). Each pass fills its part after the frame's fence (FramePass::collect).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/graph/tiler.h"
#include "renderer/graph/types.h"
#include "renderer/passes/frame_request.h"
#include "renderer/passes/pass_result.h"
#include "renderer/passes/result_slots.h"
#include "renderer/view/image.h"

namespace ds {

// One resource of the frame's graph (the inspector's Resources panel).
struct ResourceSummary {
    std::string name;
    bool is_image = true;
    VkFormat format = VK_FORMAT_UNDEFINED;  // images
    uint32_t width = 0, height = 0, samples = 1;
    graph::Semantic semantic = graph::Semantic::Other;
    // Scalar images: how they are shown. Not filled yet (Renderer's summarize copies the
    // semantic only); the read images carry it (InspectedImage::display).
    graph::Display display{};
    graph::Lifetime lifetime = graph::Lifetime::Transient;
    uint64_t bytes = 0;  // buffers
};

// msaa: how the frame was multisampled.
struct MsaaResult {
    uint32_t samples = 1;
    std::string depth_resolve;  // msaa > 1: "native-max" | "native-min" | "shader"; else ""
    // msaa > 1 and read back: pixels whose HDR colour samples are not all equal (after
    // transparent, before the resolve); exact, counted by a compute pass over every sample.
    std::optional<uint64_t> edge_pixels;
    // ReadBack::WithMsaaDepth, msaa > 1 and a D32 depth only: every depth sample (per pixel,
    // `samples` consecutive, row 0 = top) and the resolved depth (one per pixel).
    std::vector<float> depth_samples;
    std::vector<float> resolved_depth;
};

// The scene depth as the frame used it: the format depth_format gave on this device, the
// effective planes (the scene camera's, or the znear / zfar knobs) and the convention.
struct DepthResult {
    VkFormat format = VK_FORMAT_UNDEFINED;
    float znear = 0.0f, zfar = 0.0f;
    bool reverse_z = true;
};

struct FrameResult {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba8;      // final image, sRGB-encoded, tightly packed, top row first;
                                     // empty when the frame was rendered without read-back
    std::vector<PassResult> passes;  // in execution order
    double gpu_ms = 0;               // first pass start to last pass end, from timestamps
    double cpu_ms = 0;               // host time to record and submit the frame (not the wait)
    // Pixels some surface covers: depth differs from "far" after the prepass (or forward).
    // Read back with the image, or with count_fragments=on; none for ReadBack::No otherwise.
    std::optional<uint64_t> covered_pixels;
    std::vector<std::string> skipped;  // "gtao: skipped (prepass off)", in pass order
    // render_path=subpass: the render pass's tile budget and seed 002's merge verdict; none
    // on the dynamic path (no subpass group). subpass_turned_off: the knobs that are on but
    // whose passes do not run on that path, in pass order.
    std::optional<graph::TilerReport> tiler;
    std::vector<std::string> subpass_turned_off;
    MsaaResult msaa;
    std::optional<DepthResult> depth;  // every rendered frame has it
    // Every resource of the frame's graph, in creation order (the inspect pass's own target
    // left out).
    std::vector<ResourceSummary> resources;
    // InspectRequest: the image as read; none when the frame has no image of that name (its
    // pass is off) or nothing was asked. A list of requests: the first one's.
    std::optional<InspectedImage> inspected;
    // A list of requests: the images of the others that the frame has, in the list's order
    // (names it lacks are left out, so find them by name): what the viewer stacks over the
    // first and derives views from.
    std::vector<InspectedImage> overlays;
    // An image the frame read back (`inspected` or one of `overlays`), by name; null if none.
    const InspectedImage* image(std::string_view name) const {
        if (inspected && inspected->name == name) return &*inspected;
        for (const InspectedImage& i : overlays)
            if (i.name == name) return &i;
        return nullptr;
    }
    // Each pass's own result, by type (only the passes that ran put one).
    ResultSlots slots;
    template <typename T>
    const T* find() const {
        return slots.find<T>();
    }
    template <typename T>
    std::optional<T> copy_of() const {
        if (const T* v = find<T>()) return *v;
        return std::nullopt;
    }
};

}  // namespace ds
