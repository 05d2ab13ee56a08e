#pragma once
// inspect (read-back role; InspectRequest with a resource other than "final"): the
// inspector's read-back of any graph image. A compute pass "inspect" samples the image (any
// format, any sample count: a multisampled or depth image cannot be copied to a buffer as
// is) into an RGBA32F transient, and "readback_inspect" copies that to a host buffer. Added
// after every frame pass, so it sees the image as the frame left it.
#include <array>

#include <vulkan/vulkan.h>

#include "renderer/passes/compute_kernel.h"
#include "renderer/passes/frame_pass.h"

namespace ds::passes {

class InspectPass final : public FramePass {
  public:
    explicit InspectPass(const PassServices& services);

    const char* name() const override { return "inspect"; }
    graph::PassRole role() const override { return graph::PassRole::ReadBack; }
    // Adds nothing when nothing is asked, "final" is asked (read back as it is), or the
    // frame has no image of that name (its pass is off).
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) override;
    void rebuild_pipelines(vk::DestroyList& retired) override;
    // FrameResult::inspected, with everything but the camera's depth range.
    void collect(const FrameCollect& c, std::span<PassResult> own, FrameResult& frame) override;

  private:
    // By (integer source, multisampled source).
    ComputeKernel& kernel(bool uint_source, bool multisampled);

    PassServices services_;
    std::array<ComputeKernel, 4> kernels_;
    std::array<bool, 4> built_{};
    graph::ImageHandle texels_;  // this frame's, if inspecting
    InspectedImage info_;        // this frame's request: everything but the texels
};

}  // namespace ds::passes
