#pragma once
// The images a frame hands to the graph from outside, because they outlive one frame's
// transients at a fixed size: the final image (tonemap writes it), the scene depth, and with
// msaa > 1 the multisampled depth and HDR colour (count images are clear_counts' transients). Both
// depth images have the frame's depth_format: a new one recreates them. The read-back passes copy
// or probe them inside the graph (HostReadback); each import's final state is what those passes
// leave, so a frame that reads nothing back ends in the same states.
#include <cstdint>

#include <vulkan/vulkan.h>

#include "renderer/graph/graph.h"
#include "renderer/passes/frame.h"
#include "renderer/vk/destroy_list.h"
#include "renderer/vk/image.h"

namespace ds::vk {
class Context;
}

namespace ds {

class FrameTargets {
  public:
    FrameTargets(vk::Context& context, VkFormat final_format, VkFormat hdr_format);

    // (Re)creates what this frame needs at `size` with the options' sample count and depth
    // format; replaced images go to `retired` (an earlier frame may still use
    // them).
    void ensure(VkExtent2D size, const passes::FrameOptions& options, vk::DestroyList& retired);
    // Imports the final image, the depth and the multisampled images (msaa > 1) at the graph's
    // output size, as ensure() will make them, before they exist (the frame's memory estimate
    // counts them first). Fills res.final_image, res.depth and res.msaa_*.
    void import(graph::RenderGraph& graph, const passes::FrameOptions& options,
                passes::FrameResources& res) const;
    // After ensure(): the imports' handles.
    void bind(graph::RenderGraph& graph, const passes::FrameResources& res) const;

    // Releases everything (teardown, device idle).
    void reset();

  private:
    vk::Image make_image(VkFormat format, VkImageUsageFlags usage, const char* name) const;
    void ensure_depth(VkFormat format, vk::DestroyList& retired);
    void ensure_msaa(VkSampleCountFlagBits samples, vk::DestroyList& retired);
    void retire_all(vk::DestroyList& retired);

    vk::Context& context_;
    VkFormat final_format_;
    VkFormat hdr_format_;
    VkFormat depth_format_ = VK_FORMAT_UNDEFINED;  // of depth_ and msaa_depth_
    VkSampleCountFlagBits samples_ = VK_SAMPLE_COUNT_1_BIT;
    VkExtent2D size_{0, 0};
    vk::Image final_;
    vk::Image depth_;
    vk::Image msaa_depth_;  // msaa > 1 only
    vk::Image msaa_hdr_;
};

}  // namespace ds
