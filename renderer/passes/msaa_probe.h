#pragma once
// msaa_probe (read-back role; msaa > 1, frames that are read back in full): what the report
// says about the multisampled frame, measured from every sample after transparent: edge
// pixels (HDR colour samples not all equal) and, for ReadBack::WithMsaaDepth, every depth
// sample (tests compare them with the resolved depth). One compute dispatch
// (shaders/msaa_probe.comp) into a host buffer (HostReadback), whose counter the host zeroes.
#include <cstdint>

#include <vulkan/vulkan.h>

#include "renderer/passes/compute_kernel.h"
#include "renderer/passes/frame_pass.h"
#include "renderer/passes/pass_util.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/image.h"
#include "renderer/vk/pipeline.h"

namespace ds::passes {

class MsaaProbePass final : public FramePass {
  public:
    explicit MsaaProbePass(const PassServices& services);

    const char* name() const override { return "msaa_probe"; }
    graph::PassRole role() const override { return graph::PassRole::ReadBack; }
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) override;
    void rebuild_pipelines(vk::DestroyList& retired) override;
    // Back to 1x: its host buffer (every depth sample, with WithMsaaDepth) is let go.
    void on_sample_count_changed(VkSampleCountFlagBits samples) override;
    void collect(const FrameCollect& c, std::span<PassResult> own, FrameResult& frame) override;

  private:
    struct Bound {
        graph::ImageHandle depth, color;
        graph::BufferHandle out;
    };
    void record(graph::PassContext& ctx, const Bound& bound, int32_t samples, bool copy_depth);

    PassServices services_;
    vk::Sampler nearest_;
    ReadbackSet set_;               // its one set and pipeline layout
    LazyComputePipeline pipeline_;  // built by the first msaa frame that probes
    graph::BufferHandle out_;       // this frame's, if probed
    VkDeviceSize depth_values_ = 0;
};

}  // namespace ds::passes
