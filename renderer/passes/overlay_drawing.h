#pragma once
// What the transparent and decals passes share (a pass never includes another pass): surfaces
// drawn over forward's HDR image against the read-only scene depth, closer-or-equal, lit
// without prepass inputs (LightingSet with the shadow map, AO and contact shadows; their own
// normals), counting fragments into a count image when it is valid. The pipeline layout is
// {frame, material, lighting, count}; each pass builds its own pipelines on it and records its
// own draws.
#include <functional>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/graph/graph.h"
#include "renderer/passes/frame.h"
#include "renderer/passes/lighting_set.h"
#include "renderer/passes/pass_util.h"
#include "renderer/passes/pixel_history.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/pipeline.h"

namespace ds::passes {

class OverlayDrawing {
  public:
    // Binds the pipelines and draws (binding material sets with `layout`); the geometry and
    // every other set are bound already. `log`: the pixel history replay's (null for the
    // frame's own pass), whose `layout` is the replay's. `target`: render_path=subpass, the
    // subpass this draws in (its pipelines are made for it); else empty.
    using Draw =
        std::function<void(VkCommandBuffer cmd, const FrameInputs& in, VkPipelineLayout layout,
                           DrawLog* log, graph::SubpassTarget target)>;

    OverlayDrawing(const PassServices& services, const char* name);

    VkPipelineLayout layout() const { return layout_.handle(); }
    // The layout's sets (a pixel history replay layout repeats them).
    std::vector<VkDescriptorSetLayout> set_layouts() const;
    // The graph pass `name`. resolve: at msaa > 1 the rendering resolves res.msaa_hdr into
    // res.hdr, which it creates (declare_hdr_over_depth). render_path=subpass: subpass 1 of
    // kSubpassGroup (a resolve becomes the subpass's resolve attachment).
    void add(graph::RenderGraph& graph, const char* name, const FrameInputs& in,
             FrameResources& res, const CountImages& counts, bool resolve, Draw draw);
    // Pixel history: `replay`'s graph pass, before the pass, reading the depth and the HDR
    // colour the pass starts from; `draw` binds the instrumented pipelines.
    void add_history(graph::RenderGraph& graph, const FrameInputs& in, const FrameResources& res,
                     PixelHistoryReplay& replay, Draw draw);

  private:
    void record(graph::PassContext& ctx, const FrameInputs& in, const FrameResources& res,
                const LightingInputs& lighting, const CountImages& counts, bool resolve,
                const Draw& draw);

    PassServices services_;
    LightingSet lighting_;
    vk::DescriptorSetLayout count_layout_;
    vk::PipelineLayout layout_;
    FrameDescriptorPool count_sets_;
};

}  // namespace ds::passes
