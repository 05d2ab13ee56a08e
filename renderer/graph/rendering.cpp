#include "renderer/graph/rendering.h"

#include <algorithm>
#include <functional>

#include "renderer/common/error.h"

namespace ds::graph {
namespace {

using Kind = AttachmentDecl::Kind;

bool equal_extent(VkExtent2D a, VkExtent2D b) {
    return a.width == b.width && a.height == b.height;
}

VkImageLayout layout_in(const BarrierPlan& plan, uint32_t pass, uint32_t resource) {
    for (const PassUse& u : plan.passes[pass].uses)
        if (u.resource == resource) return u.use.layout;
    return VK_IMAGE_LAYOUT_UNDEFINED;
}

// The resolve declared for the attachment `resource` of `pass`, if any.
const AttachmentDecl* resolve_of(const PassInfo& pass, uint32_t resource) {
    for (const AttachmentDecl& d : pass.attachments)
        if (d.kind == Kind::Resolve && d.resolves == resource) return &d;
    return nullptr;
}

RenderingAttachment plan_attachment(const AttachmentDecl& d, uint32_t pass,
                                    std::span<const ResourceInfo> resources,
                                    std::span<const PassInfo> passes, const BarrierPlan& plan) {
    RenderingAttachment a;
    a.resource = d.resource;
    a.layout = layout_in(plan, pass, d.resource);
    a.load = attachment_load(d.load, d.resource, pass, resources, passes);
    a.store = d.read_only ? VK_ATTACHMENT_STORE_OP_NONE
                          : attachment_store(d.resource, pass, resources, passes);
    a.clear = d.clear;
    if (const AttachmentDecl* r = resolve_of(passes[pass], d.resource)) {
        a.resolve = r->resource;
        a.resolve_layout = layout_in(plan, pass, r->resource);
        a.mode = r->mode;
    }
    return a;
}

}  // namespace

VkAttachmentLoadOp attachment_load(Load load, uint32_t resource, uint32_t pass,
                                   std::span<const ResourceInfo> resources,
                                   std::span<const PassInfo> passes) {
    if (load == Load::Clear) return VK_ATTACHMENT_LOAD_OP_CLEAR;
    if (load == Load::DontCare) return VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    const ResourceInfo& r = resources[resource];
    bool written_before = false;
    for (uint32_t p = 0; p < pass && !written_before; ++p)
        for (const AccessInfo& x : passes[p].accesses)
            written_before |= x.resource == resource && is_write(x.access);
    const bool arrives_full =
        (r.lifetime == Lifetime::External && r.initial.layout != VK_IMAGE_LAYOUT_UNDEFINED) ||
        (r.history == HistoryRole::Previous && r.history_valid);
    return written_before || arrives_full ? VK_ATTACHMENT_LOAD_OP_LOAD
                                          : VK_ATTACHMENT_LOAD_OP_DONT_CARE;
}

VkAttachmentStoreOp attachment_store(uint32_t resource, uint32_t last,
                                     std::span<const ResourceInfo> resources,
                                     std::span<const PassInfo> passes) {
    bool used_after = resources[resource].lifetime != Lifetime::Transient;
    for (uint32_t p = last + 1; p < passes.size() && !used_after; ++p)
        for (const AccessInfo& x : passes[p].accesses) used_after |= x.resource == resource;
    return used_after ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_DONT_CARE;
}

RenderingPlan plan_rendering(uint32_t pass, std::span<const ResourceInfo> resources,
                             std::span<const PassInfo> passes, const BarrierPlan& plan) {
    const PassInfo& p = passes[pass];
    RenderingPlan out;
    out.extent = p.render_area;
    for (const AttachmentDecl& d : p.attachments) {
        if (d.kind == Kind::UnusedColor) {
            out.colors.emplace_back();
            continue;
        }
        const ResourceInfo& r = resources[d.resource];
        if (out.extent.width == 0) out.extent = r.extent;
        if (!equal_extent(out.extent, r.extent))
            throw Error("render graph: pass '" + p.name + "': attachment '" + r.name +
                        "' is not the size of its other attachments");
        if (d.kind == Kind::Color)
            out.colors.push_back(plan_attachment(d, pass, resources, passes, plan));
        if (d.kind == Kind::Depth) out.depth = plan_attachment(d, pass, resources, passes, plan);
        if (d.kind == Kind::Resolve) {
            const bool attached = std::any_of(
                p.attachments.begin(), p.attachments.end(), [&](const AttachmentDecl& x) {
                    return x.resource == d.resolves &&
                           (x.kind == Kind::Color || x.kind == Kind::Depth);
                });
            if (!attached)
                throw Error("render graph: pass '" + p.name + "' resolves into '" + r.name +
                            "' from an image it does not render to");
        }
    }
    return out;
}

size_t RenderTarget::hash() const {
    size_t seed = std::hash<uint64_t>{}(uint64_t(depth)) ^ (uint64_t(subpass) << 32);
    for (VkFormat f : colors) seed = seed * 31 + size_t(f);
    return seed ^ std::hash<const void*>{}(render_pass);
}

RenderTarget render_target(const PassInfo& pass, std::span<const ResourceInfo> resources) {
    RenderTarget t;
    for (const AttachmentDecl& d : pass.attachments) {
        if (d.kind == Kind::UnusedColor) t.colors.push_back(d.format);
        if (d.kind == Kind::Color) t.colors.push_back(resources[d.resource].image.format);
        if (d.kind == Kind::Depth) t.depth = resources[d.resource].image.format;
    }
    return t;
}

}  // namespace ds::graph
