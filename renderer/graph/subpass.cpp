#include "renderer/graph/subpass.h"

#include <algorithm>

#include "renderer/common/error.h"
#include "renderer/graph/rendering.h"

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

// One subpass's references, from its passes' attachment declarations: the colour slots are
// the first pass's (the others of the subpass have the same, assign_subpasses() saw to it),
// inputs and resolves are the union.
void fill_refs(const GroupPlan& g, SubpassPlan& sp, std::span<const ResourceInfo> resources,
               std::span<const PassInfo> passes, const BarrierPlan& plan) {
    using Kind = AttachmentDecl::Kind;
    bool writes_depth = false;
    std::vector<std::pair<uint32_t, AttachmentRef>> resolves;  // colour resource, resolve
    for (uint32_t p : sp.passes) {
        const bool first = p == sp.passes.front();
        for (const AttachmentDecl& d : passes[p].attachments) {
            if (d.kind == Kind::UnusedColor) {
                if (first) sp.colors.push_back({UINT32_MAX, VK_IMAGE_LAYOUT_UNDEFINED});
                continue;
            }
            const ResourceInfo& r = resources[d.resource];
            const AttachmentRef ref{attachment_index(g, d.resource),
                                    use_in(plan, p, d.resource).layout};
            if (d.kind == Kind::Color && first) sp.colors.push_back(ref);
            if (d.kind == Kind::Input) add_ref(sp.inputs, ref);
            if (d.kind == Kind::Resolve) {
                if (r.depth())
                    throw Error("render graph: subpass group '" + g.name + "': '" + r.name +
                                "': depth resolves are not planned inside a render pass");
                resolves.emplace_back(d.resolves, ref);
            }
            if (d.kind == Kind::Depth) {
                if (sp.depth && sp.depth->attachment != ref.attachment)
                    throw Error("render graph: subpass group '" + g.name + "': pass '" +
                                passes[p].name + "' attaches a second depth image '" + r.name +
                                "' in one subpass");
                sp.depth = ref;
                writes_depth |= !d.read_only;
            }
        }
    }
    sp.depth_read_only = sp.depth && !writes_depth;
    if (resolves.empty()) return;
    // One per colour slot: the resolve declared for that colour, or none.
    for (const AttachmentRef& c : sp.colors) {
        AttachmentRef ref{UINT32_MAX, {}};
        for (const auto& [colour, resolve] : resolves)
            if (c.attachment != UINT32_MAX && g.attachments[c.attachment].resource == colour)
                ref = resolve;
        sp.resolves.push_back(ref);
    }
}

// Where `pass` attaches `resource` as a colour or depth attachment.
const AttachmentDecl* attached(const PassInfo& pass, uint32_t resource) {
    for (const AttachmentDecl& d : pass.attachments)
        if (d.resource == resource &&
            (d.kind == AttachmentDecl::Kind::Color || d.kind == AttachmentDecl::Kind::Depth))
            return &d;
    return nullptr;
}

// Load and store ops and the layouts the render pass starts and ends each attachment in. A
// clear is the first use's (the render pass clears on load); a later pass cannot clear.
void fill_ops(GroupPlan& g, std::span<const ResourceInfo> resources,
              std::span<const PassInfo> passes, const BarrierPlan& plan) {
    for (GroupAttachment& a : g.attachments) {
        bool first = true;
        for (uint32_t p = g.first_pass; p <= g.last_pass; ++p) {
            const auto& uses = plan.passes[p].uses;
            if (std::none_of(uses.begin(), uses.end(),
                             [&](const PassUse& u) { return u.resource == a.resource; }))
                continue;
            const VkImageLayout layout = use_in(plan, p, a.resource).layout;
            const AttachmentDecl* d = attached(passes[p], a.resource);
            const bool clear = d && d->load == Load::Clear;
            if (clear && !first)
                throw Error("render graph: subpass group '" + g.name + "': pass '" +
                            passes[p].name + "' clears '" + resources[a.resource].name +
                            "', which an earlier subpass of the group used");
            if (first) {
                a.initial = layout;
                a.load = attachment_load(clear ? Load::Clear : Load::Keep, a.resource, p, resources,
                                         passes);
                if (clear) a.clear = d->clear;
            }
            a.final = layout;
            first = false;
        }
        a.store = attachment_store(a.resource, g.last_pass, resources, passes);
    }
}
}  // namespace

namespace {

using Kind = AttachmentDecl::Kind;

uint32_t depth_of(const PassInfo& pass, bool& read_only) {
    for (const AttachmentDecl& d : pass.attachments)
        if (d.kind == Kind::Depth) {
            read_only = d.read_only;
            return d.resource;
        }
    return kNoResource;
}

// The colour slots: resources in order (kNoResource for an unused slot).
std::vector<uint32_t> colour_slots(const PassInfo& pass) {
    std::vector<uint32_t> out;
    for (const AttachmentDecl& d : pass.attachments)
        if (d.kind == Kind::Color || d.kind == Kind::UnusedColor) out.push_back(d.resource);
    return out;
}

bool starts_subpass(const PassInfo& pass, const PassInfo& current,
                    std::span<const PassInfo> subpass) {
    bool ro = false, current_ro = false;
    depth_of(pass, ro);
    depth_of(current, current_ro);
    if (ro != current_ro || colour_slots(pass) != colour_slots(current)) return true;
    for (const AttachmentDecl& d : pass.attachments) {
        if (d.kind != Kind::Input) continue;
        for (const PassInfo& q : subpass)
            for (const AccessInfo& a : q.accesses)
                if (a.resource == d.resource && is_write(a.access)) return true;
    }
    return false;
}

void assign_run(std::span<PassInfo> run, const std::string& name) {
    uint32_t subpass = 0;
    size_t first = 0;  // of the current subpass
    for (size_t i = 0; i < run.size(); ++i) {
        if (i > 0 && starts_subpass(run[i], run[first], run.subspan(first, i - first))) {
            ++subpass;
            first = i;
        }
        run[i].group = name;
        run[i].subpass = subpass;
    }
}

}  // namespace

void assign_subpasses(std::span<PassInfo> passes, std::span<const ResourceInfo>,
                      const std::string& group) {
    for (PassInfo& p : passes) {
        p.group = p.render_pass ? p.name : std::string();
        p.subpass = 0;
    }
    if (group.empty()) return;
    uint32_t runs = 0;
    for (size_t i = 0; i < passes.size();) {
        bool ro = false;
        const uint32_t depth = passes[i].render_pass ? kNoResource : depth_of(passes[i], ro);
        size_t end = i + 1;
        while (depth != kNoResource && end < passes.size() && !passes[end].render_pass &&
               depth_of(passes[end], ro) == depth)
            ++end;
        if (end - i >= 2)
            assign_run(passes.subspan(i, end - i),
                       runs++ == 0 ? group : group + "#" + std::to_string(runs));
        i = end;
    }
}

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
