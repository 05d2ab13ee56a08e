#pragma once
// The Vulkan half of subpass groups (subpass.h): a VkRenderPass per group description, kept
// across frames (pipelines are made for it, so it must not change while the description does
// not), and each frame's framebuffer, which dies with the frame (its views may not outlive it).
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/graph/subpass.h"

namespace ds::vk {
class Context;
class DestroyList;
}  // namespace ds::vk

namespace ds::graph {

class RenderPassCache {
  public:
    explicit RenderPassCache(vk::Context& context) : context_(context) {}
    ~RenderPassCache();  // the device must be idle
    RenderPassCache(const RenderPassCache&) = delete;
    RenderPassCache& operator=(const RenderPassCache&) = delete;

    // The render pass for `group` (made on first use of its description).
    VkRenderPass get(const GroupPlan& group, std::span<const ResourceInfo> resources);
    // vkCmdBeginRenderPass2 on a framebuffer of `views` (one per attachment, in order), which
    // goes to `retired` to die after this frame; the viewport and scissor cover the render area
    // (dynamic state in every pipeline).
    void begin(VkCommandBuffer cmd, VkRenderPass pass, const GroupPlan& group,
               std::span<const VkImageView> views, vk::DestroyList& retired) const;

  private:
    struct Entry {
        std::string key;
        VkRenderPass pass = VK_NULL_HANDLE;
    };
    VkRenderPass create(const GroupPlan& group, std::span<const ResourceInfo> resources,
                        const std::string& name) const;

    vk::Context& context_;
    std::vector<Entry> passes_;
};

}  // namespace ds::graph
