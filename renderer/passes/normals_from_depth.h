#pragma once
// normals_from_depth (prepass_mode=depth): the Z-only prepass writes no normals, but GTAO, its
// spatial filter and contact shadows read them. This compute pass reconstructs world-space
// normals from the scene depth (shaders/normals_from_depth.comp: the cross product of the
// tangents towards the neighbours nearer in depth) into FrameResources::normals, an image
// named "depth_normals" (RGBA8, n * 0.5 + 0.5, semantic EncodedNormal), so those passes run
// unchanged. It runs only with the Z-only prepass and gtao or contact_shadows on; otherwise
// it has nothing to do (the G-buffer prepass writes "normals"; without a reader none are
// needed) and so reports no skip.
#include "renderer/graph/graph.h"
#include "renderer/passes/compute_kernel.h"
#include "renderer/passes/frame.h"
#include "renderer/passes/frame_pass.h"

namespace ds::passes {

class NormalsFromDepthPass final : public FramePass {
  public:
    static constexpr const char* kName = "normals_from_depth";
    static constexpr const char* kImage = "depth_normals";
    static constexpr const char* kShader = "normals_from_depth.comp";
    static constexpr VkFormat kFormat = VK_FORMAT_R8G8B8A8_UNORM;

    explicit NormalsFromDepthPass(const PassServices& services);

    const char* name() const override { return kName; }
    void rebuild_pipelines(vk::DestroyList& retired) override;
    // Whether a frame with these options runs it.
    static bool runs(const FrameOptions& o);
    // Reads res.depth; creates and writes res.normals.
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) override;

  private:
    ComputeKernel kernel_;
};

}  // namespace ds::passes
