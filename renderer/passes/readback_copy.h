#pragma once
// The frame's image read-backs, each a graph pass with the read-back role (a transfer copy
// into a host buffer, HostReadback): what the caller of Renderer::render gets back.
//   readback_final   the final image (rgba8), unless ReadBack::No;
//   readback_depth   the resolved scene depth, for covered_pixels (ReadBack::Yes /
//                    WithMsaaDepth, or count_fragments=on) and the resolved depth
//                    (WithMsaaDepth);
//   readback_counts  the count images of count_fragments=on, for each pass's
//                    shaded_fragments.
#include <vector>

#include "renderer/passes/frame_pass.h"

namespace ds::passes {

class ReadbackCopyPass final : public FramePass {
  public:
    enum class What : uint8_t { Final, Depth, Counts };

    ReadbackCopyPass(const PassServices& services, What what) : services_(services), what_(what) {}

    const char* name() const override;
    graph::PassRole role() const override { return graph::PassRole::ReadBack; }
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) override;
    void rebuild_pipelines(vk::DestroyList&) override {}  // a copy has no pipeline
    void collect(const FrameCollect& c, std::span<PassResult> own, FrameResult& frame) override;

    // Texels of a depth read-back (as HostReadback copies them) that are not "far".
    static uint64_t covered_texels(std::span<const std::byte> depth, VkFormat format,
                                   float far_depth);

  private:
    std::vector<graph::ImageHandle> images(const FrameInputs& in, const FrameResources& res) const;

    PassServices services_;
    What what_;
};

}  // namespace ds::passes
