#pragma once
// The rendering a graphics pass declares (PassBuilder::color, depth, resolve, input,
// render_area), planned: the pure half, like plan.h. A pass outside a subpass group gets one
// dynamic rendering, begun and ended by the graph around its record lambda, with the layouts
// the barrier plan gives its attachments and load and store ops from the whole frame:
//
// - Load: CLEAR where the pass declared Load::Clear, DONT_CARE where it declared
//   Load::DontCare, else (Load::Keep) LOAD where the attachment holds something (written
//   earlier this frame, or an import or history that arrives with contents), else DONT_CARE.
// - Store: NONE for a read-only depth; else STORE where anything after the pass uses the
//   image (a later pass, an import's final state, a history image), else DONT_CARE.
// - Resolves: the resolve attachment's image and layout, the mode the pass declared.
//
// Subpass groups (subpass.h) take the same load rule and plan their own store ops.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "renderer/graph/plan.h"

namespace ds::graph {

struct RenderingAttachment {
    uint32_t resource = kNoResource;  // none: an unused colour slot
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkAttachmentLoadOp load = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    VkAttachmentStoreOp store = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    VkClearValue clear{};
    uint32_t resolve = kNoResource;  // the resolve attachment, if any
    VkImageLayout resolve_layout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkResolveModeFlagBits mode = VK_RESOLVE_MODE_NONE;
};

struct RenderingPlan {
    VkExtent2D extent{0, 0};
    std::vector<RenderingAttachment> colors;  // declaration order
    std::optional<RenderingAttachment> depth;
};

// The load op of `resource` declared with `load` by pass `pass` (its first use in a subpass
// group: the group's first pass using it).
VkAttachmentLoadOp attachment_load(Load load, uint32_t resource, uint32_t pass,
                                   std::span<const ResourceInfo> resources,
                                   std::span<const PassInfo> passes);
// Whether `resource` is needed after pass `last` (STORE) or not (DONT_CARE).
VkAttachmentStoreOp attachment_store(uint32_t resource, uint32_t last,
                                     std::span<const ResourceInfo> resources,
                                     std::span<const PassInfo> passes);

// Pass `pass`'s dynamic rendering. Throws ds::Error where its attachments differ in size or
// a resolve names an attachment the pass does not render to.
RenderingPlan plan_rendering(uint32_t pass, std::span<const ResourceInfo> resources,
                             std::span<const PassInfo> passes, const BarrierPlan& plan);

// What a pipeline drawing in a pass must be made for: the colour formats in slot order (an
// unused slot keeps the format it was declared with), the depth format, and inside a subpass
// group the render pass and subpass (then the formats are the render pass's). Passes key their
// pipelines by it (PassContext::target()).
struct RenderTarget {
    std::vector<VkFormat> colors;
    VkFormat depth = VK_FORMAT_UNDEFINED;
    VkRenderPass render_pass = VK_NULL_HANDLE;
    uint32_t subpass = 0;
    bool operator==(const RenderTarget&) const = default;
    size_t hash() const;
};

// The formats of `pass`'s declared attachments (no render pass).
RenderTarget render_target(const PassInfo& pass, std::span<const ResourceInfo> resources);

}  // namespace ds::graph
