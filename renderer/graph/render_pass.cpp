#include "renderer/graph/render_pass.h"

#include <sstream>
#include <utility>

#include "renderer/format/format.h"
#include "renderer/vk/check.h"
#include "renderer/vk/context.h"
#include "renderer/vk/debug.h"
#include "renderer/vk/destroy_list.h"

namespace ds::graph {
namespace {

// Everything that makes two render passes differ: formats, samples, ops, layouts, references
// and dependencies (not the clear values, which belong to the begin).
std::string describe_group(const GroupPlan& g, std::span<const ResourceInfo> resources) {
    std::ostringstream k;
    for (const GroupAttachment& a : g.attachments) {
        const ResourceInfo& r = resources[a.resource];
        k << r.image.format << '/' << r.image.samples << '/' << a.load << a.store << '/'
          << a.initial << '/' << a.final << ';';
    }
    auto refs = [&](const std::vector<AttachmentRef>& list) {
        for (const AttachmentRef& r : list) k << r.attachment << ':' << r.layout << ',';
        k << '|';
    };
    for (const SubpassPlan& sp : g.subpasses) {
        refs(sp.colors);
        refs(sp.inputs);
        refs(sp.resolves);
        if (sp.depth) k << sp.depth->attachment << ':' << sp.depth->layout;
        k << '#';
    }
    for (const SubpassDependency& d : g.dependencies)
        k << d.src << '>' << d.dst << ':' << d.src_stages << ',' << d.dst_stages << ','
          << d.src_access << ',' << d.dst_access << ',' << d.by_region << ';';
    return k.str();
}

std::vector<VkAttachmentReference2> references(const std::vector<AttachmentRef>& list,
                                               std::span<const ResourceInfo> resources,
                                               const GroupPlan& g) {
    std::vector<VkAttachmentReference2> out;
    for (const AttachmentRef& r : list) {
        auto ref = vk::make<VkAttachmentReference2>(VK_STRUCTURE_TYPE_ATTACHMENT_REFERENCE_2);
        ref.attachment = r.attachment;
        ref.layout = r.attachment == UINT32_MAX ? VK_IMAGE_LAYOUT_UNDEFINED : r.layout;
        if (r.attachment != UINT32_MAX)
            ref.aspectMask = resources[g.attachments[r.attachment].resource].aspects();
        out.push_back(ref);
    }
    return out;
}

VkAttachmentDescription2 describe_attachment(const GroupAttachment& a, const ResourceInfo& r) {
    auto d = vk::make<VkAttachmentDescription2>(VK_STRUCTURE_TYPE_ATTACHMENT_DESCRIPTION_2);
    d.format = r.image.format;
    d.samples = r.image.samples;
    d.loadOp = a.load;
    d.storeOp = a.store;
    d.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    d.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    d.initialLayout = a.initial;
    d.finalLayout = a.final;
    return d;
}

struct FramebufferHolder {  // dies with its frame (vk::DestroyList)
    VkDevice device = VK_NULL_HANDLE;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    FramebufferHolder(VkDevice d, VkFramebuffer f) : device(d), framebuffer(f) {}
    FramebufferHolder(FramebufferHolder&& o) noexcept
        : device(o.device), framebuffer(std::exchange(o.framebuffer, VK_NULL_HANDLE)) {}
    ~FramebufferHolder() {
        if (framebuffer) vkDestroyFramebuffer(device, framebuffer, nullptr);
    }
};

}  // namespace

RenderPassCache::~RenderPassCache() {
    for (const Entry& e : passes_) vkDestroyRenderPass(context_.device(), e.pass, nullptr);
}

VkRenderPass RenderPassCache::get(const GroupPlan& group, std::span<const ResourceInfo> resources) {
    const std::string key = describe_group(group, resources);
    for (const Entry& e : passes_)
        if (e.key == key) return e.pass;
    passes_.push_back({key, create(group, resources, group.name)});
    return passes_.back().pass;
}

VkRenderPass RenderPassCache::create(const GroupPlan& g, std::span<const ResourceInfo> resources,
                                     const std::string& name) const {
    std::vector<VkAttachmentDescription2> attachments;
    for (const GroupAttachment& a : g.attachments)
        attachments.push_back(describe_attachment(a, resources[a.resource]));
    // Kept alive until vkCreateRenderPass2: the descriptions point into them.
    std::vector<std::vector<VkAttachmentReference2>> colors, inputs, resolves, depths;
    std::vector<VkSubpassDescription2> subpasses;
    for (const SubpassPlan& sp : g.subpasses) {
        colors.push_back(references(sp.colors, resources, g));
        inputs.push_back(references(sp.inputs, resources, g));
        resolves.push_back(references(sp.resolves, resources, g));
        depths.push_back(sp.depth ? references({*sp.depth}, resources, g)
                                  : std::vector<VkAttachmentReference2>{});
    }
    for (size_t i = 0; i < g.subpasses.size(); ++i) {
        auto d = vk::make<VkSubpassDescription2>(VK_STRUCTURE_TYPE_SUBPASS_DESCRIPTION_2);
        d.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
        d.colorAttachmentCount = uint32_t(colors[i].size());
        d.pColorAttachments = colors[i].data();
        d.inputAttachmentCount = uint32_t(inputs[i].size());
        d.pInputAttachments = inputs[i].data();
        d.pResolveAttachments = resolves[i].empty() ? nullptr : resolves[i].data();
        d.pDepthStencilAttachment = depths[i].empty() ? nullptr : depths[i].data();
        subpasses.push_back(d);
    }
    // Synchronization2's masks ride in a VkMemoryBarrier2 (the 32-bit ones are then ignored).
    std::vector<VkMemoryBarrier2> barriers(g.dependencies.size());
    std::vector<VkSubpassDependency2> dependencies;
    for (size_t i = 0; i < g.dependencies.size(); ++i) {
        const SubpassDependency& s = g.dependencies[i];
        barriers[i] = vk::make<VkMemoryBarrier2>(VK_STRUCTURE_TYPE_MEMORY_BARRIER_2);
        barriers[i].srcStageMask = s.src_stages;
        barriers[i].srcAccessMask = s.src_access;
        barriers[i].dstStageMask = s.dst_stages;
        barriers[i].dstAccessMask = s.dst_access;
        auto d = vk::make<VkSubpassDependency2>(VK_STRUCTURE_TYPE_SUBPASS_DEPENDENCY_2);
        d.pNext = &barriers[i];
        d.srcSubpass = s.src;
        d.dstSubpass = s.dst;
        d.dependencyFlags = s.by_region ? VK_DEPENDENCY_BY_REGION_BIT : 0;
        dependencies.push_back(d);
    }
    auto info = vk::make<VkRenderPassCreateInfo2>(VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO_2);
    info.attachmentCount = uint32_t(attachments.size());
    info.pAttachments = attachments.data();
    info.subpassCount = uint32_t(subpasses.size());
    info.pSubpasses = subpasses.data();
    info.dependencyCount = uint32_t(dependencies.size());
    info.pDependencies = dependencies.data();
    VkRenderPass pass = VK_NULL_HANDLE;
    vk::check(vkCreateRenderPass2(context_.device(), &info, nullptr, &pass), "vkCreateRenderPass2");
    context_.debug().set_name(context_.device(), VK_OBJECT_TYPE_RENDER_PASS, pass, name.c_str());
    return pass;
}

void RenderPassCache::begin(VkCommandBuffer cmd, VkRenderPass pass, const GroupPlan& g,
                            std::span<const VkImageView> views, vk::DestroyList& retired) const {
    auto fb = vk::make<VkFramebufferCreateInfo>(VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO);
    fb.renderPass = pass;
    fb.attachmentCount = uint32_t(views.size());
    fb.pAttachments = views.data();
    fb.width = g.extent.width;
    fb.height = g.extent.height;
    fb.layers = 1;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    vk::check(vkCreateFramebuffer(context_.device(), &fb, nullptr, &framebuffer),
              "vkCreateFramebuffer");
    retired.defer(FramebufferHolder(context_.device(), framebuffer));
    std::vector<VkClearValue> clears;
    for (const GroupAttachment& a : g.attachments) clears.push_back(a.clear);
    auto begin = vk::make<VkRenderPassBeginInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO);
    begin.renderPass = pass;
    begin.framebuffer = framebuffer;
    begin.renderArea = {{0, 0}, g.extent};
    begin.clearValueCount = uint32_t(clears.size());
    begin.pClearValues = clears.data();
    auto contents = vk::make<VkSubpassBeginInfo>(VK_STRUCTURE_TYPE_SUBPASS_BEGIN_INFO);
    contents.contents = VK_SUBPASS_CONTENTS_INLINE;
    vkCmdBeginRenderPass2(cmd, &begin, &contents);
    // Every pipeline takes viewport and scissor as dynamic state; a subpass's pass records
    // draws only, so the render area is set for it, as begin_rendering() does for the others.
    const VkViewport viewport{0.0f, 0.0f, float(g.extent.width), float(g.extent.height),
                              0.0f, 1.0f};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &begin.renderArea);
}

}  // namespace ds::graph
