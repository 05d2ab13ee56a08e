#include "renderer/graph/subpass.h"

#include <algorithm>

#include "renderer/common/error.h"

namespace ds::graph {
namespace {

bool attaches(Access access) {
    return access == Access::ColorAttachment || access == Access::DepthAttachment ||
           access == Access::DepthReadOnly || access == Access::ResolveDst ||
           access == Access::InputAttachment;
}

bool in_group(const GroupPlan& g, uint32_t pass) {
    return pass >= g.first_pass && pass <= g.last_pass;
}

bool same_size(VkExtent2D a, VkExtent2D b) {
    return a.width == b.width && a.height == b.height;
}

// Which of the group's resources are attachments, in first-declaration order; and the size.
void collect_attachments(GroupPlan& g, std::span<const ResourceInfo> resources,
                         std::span<const PassInfo> passes) {
    for (uint32_t p = g.first_pass; p <= g.last_pass; ++p) {
        for (const AccessInfo& a : passes[p].accesses) {
            if (!attaches(a.access)) continue;
            const ResourceInfo& r = resources[a.resource];
            if (g.attachments.empty()) g.extent = r.extent;
            if (!same_size(g.extent, r.extent))
                throw Error("render graph: subpass group '" + g.name + "': '" + r.name +
                            "' is not the size of the group's other attachments");
            auto same = [&](const GroupAttachment& x) { return x.resource == a.resource; };
            if (std::none_of(g.attachments.begin(), g.attachments.end(), same))
                g.attachments.push_back({.resource = a.resource});
        }
    }
}

// Owned by the graph and touched by nobody but this group, as an attachment: tile memory.
bool only_in_group(const GroupPlan& g, uint32_t resource, std::span<const ResourceInfo> resources,
                   std::span<const PassInfo> passes) {
    if (resources[resource].lifetime != Lifetime::Transient) return false;
    for (uint32_t p = 0; p < passes.size(); ++p)
        for (const AccessInfo& a : passes[p].accesses)
            if (a.resource == resource && (!in_group(g, p) || !attaches(a.access))) return false;
    return true;
}

void start_group(std::vector<GroupPlan>& groups, const PassInfo& pass, uint32_t index) {
    for (const GroupPlan& g : groups)
        if (g.name == pass.group)
            throw Error("render graph: subpass group '" + pass.group + "' comes back at pass '" +
                        pass.name + "' after other passes: a render pass is one run of passes");
    if (pass.subpass != 0)
        throw Error("render graph: pass '" + pass.name + "' starts subpass group '" + pass.group +
                    "' at subpass " + std::to_string(pass.subpass) + ", not 0");
    GroupPlan g;
    g.name = pass.group;
    g.first_pass = g.last_pass = index;
    SubpassPlan first;
    first.passes = {index};
    g.subpasses.push_back(std::move(first));
    groups.push_back(std::move(g));
}

void extend_group(GroupPlan& g, const PassInfo& pass, uint32_t index) {
    const uint32_t last = uint32_t(g.subpasses.size() - 1);
    if (pass.subpass != last && pass.subpass != last + 1)
        throw Error("render graph: pass '" + pass.name + "' is subpass " +
                    std::to_string(pass.subpass) + " of group '" + g.name + "' after subpass " +
                    std::to_string(last) + ": subpasses go in order, one step at a time");
    if (pass.subpass == last + 1) g.subpasses.emplace_back();
    g.subpasses.back().passes.push_back(index);
    g.last_pass = index;
}

uint32_t attachment_index(const GroupPlan& g, uint32_t resource) {
    for (uint32_t i = 0; i < g.attachments.size(); ++i)
        if (g.attachments[i].resource == resource) return i;
    return UINT32_MAX;
}

// The resource's merged use in one pass (plan.passes[pass].uses).
Use use_in(const BarrierPlan& plan, uint32_t pass, uint32_t resource) {
    for (const PassUse& u : plan.passes[pass].uses)
        if (u.resource == resource) return u.use;
    return {};
}

void add_ref(std::vector<AttachmentRef>& refs, AttachmentRef ref) {
    auto same = [&](const AttachmentRef& r) { return r.attachment == ref.attachment; };
    if (std::none_of(refs.begin(), refs.end(), same)) refs.push_back(ref);
}

// One subpass's references, from its passes' accesses in declaration order.
void fill_refs(const GroupPlan& g, SubpassPlan& sp, std::span<const ResourceInfo> resources,
               std::span<const PassInfo> passes, const BarrierPlan& plan) {
    std::vector<AttachmentRef> resolves;
    bool writes_depth = false;
    for (uint32_t p : sp.passes) {
        for (const AccessInfo& a : passes[p].accesses) {
            if (!attaches(a.access)) continue;
            const ResourceInfo& r = resources[a.resource];
            const AttachmentRef ref{attachment_index(g, a.resource),
                                    use_in(plan, p, a.resource).layout};
            if (a.access == Access::ColorAttachment) add_ref(sp.colors, ref);
            if (a.access == Access::InputAttachment) add_ref(sp.inputs, ref);
            if (a.access == Access::ResolveDst) {
                if (r.depth())
                    throw Error("render graph: subpass group '" + g.name + "': '" + r.name +
                                "': depth resolves are not planned inside a render pass");
                add_ref(resolves, ref);
            }
            if (a.access == Access::DepthAttachment || a.access == Access::DepthReadOnly) {
                if (sp.depth && sp.depth->attachment != ref.attachment)
                    throw Error("render graph: subpass group '" + g.name + "': pass '" +
                                passes[p].name + "' attaches a second depth image '" + r.name +
                                "' in one subpass");
                sp.depth = ref;
                writes_depth |= a.access == Access::DepthAttachment;
            }
        }
    }
    sp.depth_read_only = sp.depth && !writes_depth;
    if (resolves.empty()) return;
    // The i-th resolve destination takes the i-th multisampled colour attachment.
    size_t next = 0;
    for (const AttachmentRef& c : sp.colors) {
        const bool ms = resources[g.attachments[c.attachment].resource].multisampled();
        sp.resolves.push_back(ms && next < resolves.size() ? resolves[next++]
                                                           : AttachmentRef{UINT32_MAX, {}});
    }
    if (next != resolves.size())
        throw Error("render graph: subpass group '" + g.name +
                    "': more resolve destinations than multisampled colour attachments");
}

// Load and store ops and the layouts the render pass starts and ends each attachment in.
void fill_ops(GroupPlan& g, std::span<const ResourceInfo> resources,
              std::span<const PassInfo> passes, const BarrierPlan& plan) {
    for (GroupAttachment& a : g.attachments) {
        const ResourceInfo& r = resources[a.resource];
        bool first = true;
        for (uint32_t p = g.first_pass; p <= g.last_pass; ++p) {
            const auto& uses = plan.passes[p].uses;
            if (std::none_of(uses.begin(), uses.end(),
                             [&](const PassUse& u) { return u.resource == a.resource; }))
                continue;
            const VkImageLayout layout = use_in(plan, p, a.resource).layout;
            if (first) a.initial = layout;
            a.final = layout;
            if (first)
                for (const AttachmentClear& c : passes[p].clears)
                    if (c.resource == a.resource) {
                        a.load = VK_ATTACHMENT_LOAD_OP_CLEAR;
                        a.clear = c.value;
                    }
            first = false;
        }
        bool written_before = false, used_after = false;
        for (uint32_t p = 0; p < passes.size(); ++p)
            for (const AccessInfo& x : passes[p].accesses) {
                if (x.resource != a.resource) continue;
                written_before |= p < g.first_pass && is_write(x.access);
                used_after |= p > g.last_pass;
            }
        const bool arrives_full =
            (r.lifetime == Lifetime::External && r.initial.layout != VK_IMAGE_LAYOUT_UNDEFINED) ||
            (r.history == HistoryRole::Previous && r.history_valid);
        if (a.load != VK_ATTACHMENT_LOAD_OP_CLEAR && (written_before || arrives_full))
            a.load = VK_ATTACHMENT_LOAD_OP_LOAD;
        const bool kept = used_after || r.lifetime != Lifetime::Transient;
        a.store = kept ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_DONT_CARE;
    }
}
}  // namespace

std::vector<GroupPlan> find_subpass_groups(std::span<const ResourceInfo> resources,
                                           std::span<const PassInfo> passes) {
    std::vector<GroupPlan> groups;
    for (uint32_t i = 0; i < passes.size(); ++i) {
        const PassInfo& pass = passes[i];
        if (pass.group.empty()) {
            for (const AccessInfo& a : pass.accesses)
                if (a.access == Access::InputAttachment)
                    throw Error("render graph: pass '" + pass.name + "' reads '" +
                                resources[a.resource].name +
                                "' as an input attachment outside a subpass group");
            continue;
        }
        const bool continues =
            !groups.empty() && groups.back().name == pass.group && groups.back().last_pass + 1 == i;
        if (continues)
            extend_group(groups.back(), pass, i);
        else
            start_group(groups, pass, i);
    }
    for (GroupPlan& g : groups) {
        collect_attachments(g, resources, passes);
        for (GroupAttachment& a : g.attachments)
            a.transient = only_in_group(g, a.resource, resources, passes);
    }
    return groups;
}

std::vector<StoreWrite> store_writes(std::span<const GroupPlan> groups,
                                     std::span<const PassInfo> passes) {
    std::vector<StoreWrite> out;
    for (const GroupPlan& g : groups)
        for (const GroupAttachment& a : g.attachments)
            for (uint32_t p = g.last_pass + 1; p-- > g.first_pass;) {
                const auto& accesses = passes[p].accesses;
                if (std::any_of(accesses.begin(), accesses.end(),
                                [&](const AccessInfo& x) { return x.resource == a.resource; })) {
                    out.push_back({p, a.resource});
                    break;
                }
            }
    return out;
}

int group_of(std::span<const GroupPlan> groups, uint32_t pass) {
    for (size_t i = 0; i < groups.size(); ++i)
        if (in_group(groups[i], pass)) return int(i);
    return -1;
}

const char* load_op_name(VkAttachmentLoadOp op) {
    switch (op) {
        case VK_ATTACHMENT_LOAD_OP_CLEAR:
            return "clear";
        case VK_ATTACHMENT_LOAD_OP_LOAD:
            return "load";
        default:
            return "dont_care";
    }
}

const char* store_op_name(VkAttachmentStoreOp op) {
    return op == VK_ATTACHMENT_STORE_OP_STORE ? "store" : "dont_care";
}

}  // namespace ds::graph

namespace ds::graph {
namespace {

// A subpass's merged use of a resource: the union over its passes.
Use subpass_use(const SubpassPlan& sp, const BarrierPlan& plan, uint32_t resource) {
    Use u;
    for (uint32_t p : sp.passes) {
        const Use x = use_in(plan, p, resource);
        u.stages |= x.stages;
        u.access |= x.access;
    }
    return u;
}

void fill_dependencies(GroupPlan& g, const BarrierPlan& plan) {
    for (uint32_t j = 1; j < g.subpasses.size(); ++j) {
        for (uint32_t i = 0; i < j; ++i) {
            SubpassDependency d{.src = i, .dst = j};
            for (const GroupAttachment& a : g.attachments) {
                const Use before = subpass_use(g.subpasses[i], plan, a.resource);
                const Use after = subpass_use(g.subpasses[j], plan, a.resource);
                if (!before.stages || !after.stages) continue;
                if (!write_bits(before.access) && !write_bits(after.access)) continue;
                d.src_stages |= before.stages;
                d.src_access |= write_bits(before.access);
                d.dst_stages |= after.stages;
                d.dst_access |= after.access;
            }
            if (d.src_stages) g.dependencies.push_back(d);
        }
    }
}

// A resource other than an attachment, written by one pass of the group and used by a later
// one, needs a barrier the render pass cannot hold.
void check_other_resources(const GroupPlan& g, std::span<const ResourceInfo> resources,
                           std::span<const PassInfo> passes) {
    for (uint32_t p = g.first_pass; p <= g.last_pass; ++p)
        for (const AccessInfo& w : passes[p].accesses) {
            if (!is_write(w.access) || attachment_index(g, w.resource) != UINT32_MAX) continue;
            for (uint32_t q = p + 1; q <= g.last_pass; ++q)
                for (const AccessInfo& x : passes[q].accesses)
                    if (x.resource == w.resource)
                        throw Error("render graph: subpass group '" + g.name + "': '" +
                                    resources[w.resource].name + "' is written by pass '" +
                                    passes[p].name + "' and used by pass '" + passes[q].name +
                                    "': no barrier can sit between them inside a render pass");
        }
}

// The group's passes record no barriers: the first use of each resource is prepared before
// the render pass begins; the rest are the render pass's own dependencies and transitions.
void move_barriers(GroupPlan& g, BarrierPlan& plan) {
    std::vector<uint32_t> seen;
    for (uint32_t p = g.first_pass; p <= g.last_pass; ++p) {
        for (const Barrier& b : plan.passes[p].barriers) {
            const bool attachment = attachment_index(g, b.resource) != UINT32_MAX;
            const bool first = std::find(seen.begin(), seen.end(), b.resource) == seen.end();
            if (!attachment || first) g.barriers.push_back(b);
        }
        plan.passes[p].barriers.clear();
        for (const PassUse& u : plan.passes[p].uses) seen.push_back(u.resource);
    }
}

}  // namespace

void plan_subpass_groups(std::vector<GroupPlan>& groups, std::span<const ResourceInfo> resources,
                         std::span<const PassInfo> passes, BarrierPlan& plan) {
    for (GroupPlan& g : groups) {
        check_other_resources(g, resources, passes);
        for (SubpassPlan& sp : g.subpasses) fill_refs(g, sp, resources, passes, plan);
        fill_ops(g, resources, passes, plan);
        fill_dependencies(g, plan);
        move_barriers(g, plan);
    }
}

}  // namespace ds::graph
