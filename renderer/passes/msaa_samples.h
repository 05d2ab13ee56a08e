#pragma once
// msaa_samples (read-back role; frames with a SampleQuery, the inspector's sample view, issue
// 15): every sample of the asked rectangle as the frame left it, after transparent and before
// any resolve: the winning surface (the prepass's per-sample surface ids, res.msaa_surface_id;
// the renderer turns surface_id on for such frames), the depth and the HDR colour. At msaa=1
// the single-sample depth, HDR and surface_id images. One compute dispatch
// (shaders/msaa_samples.comp) into a host buffer (HostReadback); an MsaaSamples in the frame's
// slots. Without a query nothing of it runs (no pass; the pipelines are built on first use).
#include <array>
#include <cstdint>

#include <vulkan/vulkan.h>

#include "renderer/common/surface_name.h"
#include "renderer/passes/compute_kernel.h"
#include "renderer/passes/frame_pass.h"
#include "renderer/passes/pass_util.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/image.h"
#include "renderer/vk/pipeline.h"

namespace ds {

// The MSAA sample view (issue 15): every sample of a rectangle of the frame, as the frame left
// it (after transparent, before any resolve): the winning surface (the prepass's per-sample
// surface_id; 0 none), the depth and the HDR colour. At msaa=1 the one sample is the pixel.
struct PixelSample {
    uint32_t surface = 0;  // Renderer::describe_surface; 0 nothing (or surface_ids is false)
    float depth = 0;       // as the depth format stores it (reverse-Z unless off)
    std::array<float, 4> color{};
};
struct MsaaSamples {
    SampleQuery rect;  // as read: clamped to the frame
    uint32_t samples = 1;
    bool surface_ids = false;  // false: no prepass this frame, so no surface per sample
    // Per pixel of `rect`, row by row, `samples` consecutive.
    std::vector<PixelSample> values;
    bool contains(uint32_t x, uint32_t y) const {
        return x >= rect.x && y >= rect.y && x - rect.x < rect.width && y - rect.y < rect.height;
    }
    // The samples of frame pixel (x, y); empty outside `rect`.
    std::span<const PixelSample> pixel(uint32_t x, uint32_t y) const {
        if (!contains(x, y) || values.empty()) return {};
        const size_t i = (size_t(y - rect.y) * rect.width + (x - rect.x)) * samples;
        return std::span(values).subspan(i, samples);
    }
};

}  // namespace ds

namespace ds::passes {

// std430 twin of Sample in shaders/msaa_samples.comp.
struct SampleRecord {
    uint32_t surface = 0;
    float depth = 0;
    uint32_t pad[2] = {};
    std::array<float, 4> color{};
};
static_assert(sizeof(SampleRecord) == 32);

class MsaaSamplesPass final : public FramePass {
  public:
    // The most pixels one query may read (the sample view asks for the viewer's visible
    // texels when zoomed in: a few tens of thousands).
    static constexpr uint64_t kMaxPixels = 1u << 20;

    explicit MsaaSamplesPass(const PassServices& services);

    const char* name() const override { return "msaa_samples"; }
    // The sample view names the surface of every sample: it asks the prepass for surface ids
    // (on the dynamic path, where the device has geometry shaders).
    void configure(const FrameSetup& setup, FrameOptions& options) override;
    graph::PassRole role() const override { return graph::PassRole::ReadBack; }
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) override;
    void rebuild_pipelines(vk::DestroyList& retired) override;
    void collect(const FrameCollect& c, std::span<PassResult> own, FrameResult& frame) override;

  private:
    struct Bound {
        graph::ImageHandle depth, color, surface;  // surface invalid: no prepass
        graph::BufferHandle out;
    };
    // By (multisampled, surface ids).
    LazyComputePipeline& pipeline(bool multisampled, bool surface_ids);
    void record(graph::PassContext& ctx, const Bound& bound, bool multisampled);

    PassServices services_;
    vk::Sampler nearest_;
    ReadbackSet set_;  // its one set and pipeline layout
    std::array<LazyComputePipeline, 4> pipelines_;
    // This frame's query, clamped to the frame, and its buffer (invalid: none).
    SampleQuery rect_;
    uint32_t samples_ = 1;
    bool surface_ids_ = false;
    graph::BufferHandle out_;
};

}  // namespace ds::passes
