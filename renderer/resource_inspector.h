#pragma once
// The inspector's read-back of any graph image (Renderer::render's `inspect`): a compute pass
// "inspect", added last to the frame's graph, samples the image (any format, any sample
// count: a multisampled or depth image cannot be copied to a buffer as is) into an imported
// RGBA32F image, which is copied to a host buffer after the graph. The graph places the
// barriers like for any other pass, so the pass sees the image as the frame left it.
#include <array>
#include <optional>
#include <string_view>

#include <vulkan/vulkan.h>

#include "renderer/graph/graph.h"
#include "renderer/passes/compute_kernel.h"
#include "renderer/passes/frame.h"
#include "renderer/renderer.h"
#include "renderer/vk/buffer.h"
#include "renderer/vk/image.h"

namespace ds {

class ResourceInspector {
  public:
    static constexpr const char* kPassName = "inspect";

    explicit ResourceInspector(const passes::PassServices& services);

    // Adds the pass when the frame has an image `name`; false (no pass) when it has none.
    // Replaced images go to `retired`.
    bool add(graph::RenderGraph& graph, const passes::FrameInputs& in, std::string_view name,
             uint32_t sample, vk::DestroyList& retired);
    // After graph.execute(), when add() returned true.
    void record_read_back(VkCommandBuffer cmd) const;
    // After the fence: the texels, with everything but the camera's depth range filled in.
    InspectedImage result() const;

    void rebuild_pipelines(vk::DestroyList& retired);

  private:
    // By (integer source, multisampled source).
    passes::ComputeKernel& kernel(bool uint_source, bool multisampled);
    void ensure_target(VkExtent2D extent, vk::DestroyList& retired);

    vk::Context& context_;
    std::array<passes::ComputeKernel, 4> kernels_;
    std::array<bool, 4> built_{};
    vk::Image texels_;  // RGBA32F at the inspected image's size
    vk::Buffer readback_;
    InspectedImage info_;  // the last add(): everything but the texels
};

}  // namespace ds
