#include "renderer/graph/plan.h"

#include <algorithm>

#include "renderer/format/format.h"

namespace ds::graph {
namespace {

bool is_attachment(Access access) {
    return access == Access::ColorAttachment || access == Access::DepthAttachment ||
           access == Access::DepthReadOnly;
}

VkImageLayout combined_layout(VkImageLayout a, VkImageLayout b) {
    if (a == b) return a;
    auto read_only = [](VkImageLayout l) {
        return l == VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL ||
               l == VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    };
    // Depth test without writes while sampling the same depth: one read-only layout serves both.
    if (read_only(a) && read_only(b)) return VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;
    return VK_IMAGE_LAYOUT_GENERAL;
}

bool contains(VkFlags64 outer, VkFlags64 inner) {
    return (inner & ~outer) == 0;
}

// Whether a read needs no barrier because the last write is already visible to it.
bool is_visible(const ResourceState& s, const Use& use) {
    if (s.write_stages == VK_PIPELINE_STAGE_2_NONE) return true;  // nothing it could miss
    return std::any_of(s.visible.begin(), s.visible.end(), [&](const StageAccess& v) {
        return contains(v.stages, use.stages) && contains(v.access, use.access);
    });
}

// The barrier (if any) that makes `use` safe after `s`; updates `s` to the state after it.
std::optional<Barrier> step(ResourceState& s, const Use& use, uint32_t resource, bool image) {
    const VkAccessFlags2 writes = write_bits(use.access);
    const bool transition = image && s.layout != use.layout;
    if (!writes && !transition && is_visible(s, use)) {  // read after read, same layout
        s.read_stages |= use.stages;
        return std::nullopt;
    }
    Barrier b;
    b.resource = resource;
    b.is_image = image;
    b.old_layout = s.layout;
    b.new_layout = use.layout;
    if ((writes || transition) && s.read_stages != VK_PIPELINE_STAGE_2_NONE) {
        // Write after read (a transition writes too): waiting for the readers is enough, the
        // write before them is ordered through them and was made available already.
        b.src_stages = s.read_stages;
        // A real write before those reads (not a transition's): the validation layer's
        // synchronization check wants a later layout transition to name it again.
        if (transition && s.write_access) {
            b.src_stages |= s.write_stages;
            b.src_access = s.write_access;
        }
    } else {
        b.src_stages = s.write_stages;
        b.src_access = s.write_access;
    }
    b.dst_stages = use.stages;
    b.dst_access = use.access;

    if (writes) {
        s = ResourceState{use.layout, use.stages, writes, VK_PIPELINE_STAGE_2_NONE, {}};
    } else if (transition) {
        s = ResourceState{
            use.layout, use.stages, VK_ACCESS_2_NONE, use.stages, {{use.stages, use.access}}};
    } else {
        s.read_stages |= use.stages;
        s.visible.push_back({use.stages, use.access});
    }
    // Nothing earlier to wait for (a fresh buffer), or nobody after (a final state that needs
    // no stage): only a layout change still needs the barrier.
    const bool no_dependency =
        b.src_stages == VK_PIPELINE_STAGE_2_NONE || b.dst_stages == VK_PIPELINE_STAGE_2_NONE;
    if (!transition && no_dependency) return std::nullopt;
    return b;
}

}  // namespace

ResourceState ResourceState::from_external(const ExternalState& state) {
    ResourceState s;
    s.layout = state.layout;
    if (write_bits(state.access)) {
        s.write_stages = state.stages;
        s.write_access = write_bits(state.access);
    } else {
        s.read_stages = state.stages;  // e.g. a swapchain acquire's wait stage
    }
    return s;
}

ResourceState ResourceState::discarded() const {
    ResourceState s = *this;
    s.layout = VK_IMAGE_LAYOUT_UNDEFINED;
    return s;
}

bool ResourceInfo::depth() const {
    return is_image && (format::aspect_flags(image.format) &
                        (VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT)) != 0;
}

VkImageAspectFlags ResourceInfo::aspects() const {
    return is_image ? format::aspect_flags(image.format) : 0;
}

std::vector<PassUse> merge_uses(const PassInfo& pass, std::span<const ResourceInfo> resources) {
    const bool resolves =
        std::any_of(pass.accesses.begin(), pass.accesses.end(),
                    [](const AccessInfo& a) { return a.access == Access::ResolveDst; });
    std::vector<PassUse> uses;
    for (const AccessInfo& a : pass.accesses) {
        const ResourceInfo& r = resources[a.resource];
        Use use = describe(a.access, a.shader, r.depth());
        if (!r.is_image) use.layout = VK_IMAGE_LAYOUT_UNDEFINED;
        // A resolve reads its multisampled attachments in COLOR_ATTACHMENT_OUTPUT (for depth
        // too): the next writer of those attachments has to wait for that stage as well.
        if (resolves && r.multisampled() && is_attachment(a.access)) {
            use.stages |= VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
            use.access |= VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT;
        }
        auto same = [&](const PassUse& u) { return u.resource == a.resource; };
        auto it = std::find_if(uses.begin(), uses.end(), same);
        if (it == uses.end()) {
            uses.push_back({a.resource, use});
            continue;
        }
        it->use.layout = combined_layout(it->use.layout, use.layout);
        it->use.stages |= use.stages;
        it->use.access |= use.access;
    }
    return uses;
}

BarrierPlan plan_barriers(std::span<const ResourceInfo> resources, std::span<const PassInfo> passes,
                          std::span<const StoreWrite> store_writes) {
    BarrierPlan plan;
    std::vector<ResourceState> states;
    states.reserve(resources.size());
    for (const ResourceInfo& r : resources) states.push_back(r.initial);

    for (uint32_t index = 0; index < passes.size(); ++index) {
        PassPlan p;
        p.uses = merge_uses(passes[index], resources);
        for (const StoreWrite& w : store_writes) {
            if (w.pass != index) continue;
            for (PassUse& u : p.uses) {
                if (u.resource != w.resource) continue;
                const bool depth = resources[u.resource].depth();
                u.use.stages |= depth ? VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT
                                      : VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
                u.use.access |= depth ? VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT
                                      : VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
            }
        }
        for (const PassUse& u : p.uses) {
            const bool image = resources[u.resource].is_image;
            if (auto b = step(states[u.resource], u.use, u.resource, image))
                p.barriers.push_back(*b);
        }
        plan.passes.push_back(std::move(p));
    }
    for (uint32_t i = 0; i < resources.size(); ++i) {
        const ResourceInfo& r = resources[i];
        if (!r.final) continue;
        Use use{r.final->layout, r.final->stages, r.final->access};
        // UNDEFINED as a final layout means "leave it as the last pass used it".
        if (!r.is_image || use.layout == VK_IMAGE_LAYOUT_UNDEFINED) use.layout = states[i].layout;
        if (auto b = step(states[i], use, i, r.is_image)) plan.final_barriers.push_back(*b);
    }
    plan.end_states = std::move(states);
    return plan;
}

std::vector<VkFlags> derive_usage(std::span<const ResourceInfo> resources,
                                  std::span<const PassInfo> passes) {
    std::vector<VkFlags> usage;
    usage.reserve(resources.size());
    for (const ResourceInfo& r : resources)
        usage.push_back(r.is_image ? VkFlags(VK_IMAGE_USAGE_TRANSFER_SRC_BIT)
                                   : VkFlags(VK_BUFFER_USAGE_TRANSFER_SRC_BIT));
    for (const PassInfo& pass : passes) {
        for (const AccessInfo& a : pass.accesses) {
            const ResourceInfo& r = resources[a.resource];
            usage[a.resource] |=
                r.is_image ? image_usage(a.access, r.depth()) : buffer_usage(a.access);
        }
    }
    return usage;
}

}  // namespace ds::graph
