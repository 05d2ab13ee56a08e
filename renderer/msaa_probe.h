#pragma once
// msaa > 1: what the report says about the multisampled frame, measured after the graph from
// the images FrameTargets keeps sampleable: edge pixels (HDR colour samples not all equal)
// and, on request, every depth sample (tests compare them with the resolved depth).
// One compute dispatch (shaders/msaa_probe.comp) into a host-visible buffer.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/vk/buffer.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/image.h"
#include "renderer/vk/pipeline.h"

namespace ds::shader {
class Compiler;
}
namespace ds::vk {
class Context;
}

namespace ds {

class MsaaProbe {
  public:
    MsaaProbe(vk::Context& context, shader::Compiler& compiler);

    // After graph.execute(): `depth` in DEPTH_STENCIL_READ_ONLY_OPTIMAL and `color` in
    // SHADER_READ_ONLY_OPTIMAL, both visible to compute reads. The caller waits for the
    // frame's fence before the next record (Renderer::render does), so one buffer suffices.
    void record(VkCommandBuffer cmd, const vk::Image& depth, const vk::Image& color,
                bool copy_depth);

    // After the fence.
    uint64_t edge_pixels() const;
    std::vector<float> depth_samples() const;  // empty unless copy_depth

  private:
    vk::Context& context_;
    vk::Sampler nearest_;
    vk::DescriptorSetLayout set_layout_;
    vk::DescriptorPool pool_;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    vk::PipelineLayout layout_;
    vk::Pipeline pipeline_;
    vk::Buffer buffer_;
    VkDeviceSize depth_values_ = 0;  // copied by the last record()
};

}  // namespace ds
