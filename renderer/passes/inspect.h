#pragma once
// inspect (read-back role; InspectRequests naming resources other than "final"): the
// inspector's read-back of graph images. A compute pass "inspect" samples each image (any
// format, any sample count: a multisampled or depth image cannot be copied to a buffer as
// is) into an RGBA32F transient of its own, one dispatch each, and "readback_inspect" copies
// them to host buffers. Added after every frame pass, so it sees the images as the frame left
// them.
#include <array>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/passes/compute_kernel.h"
#include "renderer/passes/frame_pass.h"

namespace ds::passes {

class InspectPass final : public FramePass {
  public:
    // Images one frame reads at most (the primary one and overlays); later ones are left out.
    static constexpr uint32_t kMaxImages = 16;

    explicit InspectPass(const PassServices& services);

    const char* name() const override { return "inspect"; }
    graph::PassRole role() const override { return graph::PassRole::ReadBack; }
    // Adds nothing when nothing is asked, only "final" is asked (read back as it is), or the
    // frame has none of the images asked for (their passes are off).
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) override;
    void rebuild_pipelines(vk::DestroyList& retired) override;
    // FrameResult::inspected and ::overlays, with everything but the camera's depth range.
    void collect(const FrameCollect& c, std::span<PassResult> own, FrameResult& frame) override;

  private:
    // One image read this frame.
    struct Read {
        graph::ImageHandle source, texels;
        InspectedImage info;  // everything but the texels
        bool primary = false;
    };
    // By (integer source, multisampled source).
    ComputeKernel& kernel(bool uint_source, bool multisampled);
    // The reads `in.inspect` asks for that this frame's graph has, in its order.
    std::vector<Read> plan(const graph::RenderGraph& graph, const FrameInputs& in) const;

    PassServices services_;
    std::array<ComputeKernel, 4> kernels_;
    std::array<bool, 4> built_{};
    std::vector<Read> reads_;  // this frame's
};

}  // namespace ds::passes
