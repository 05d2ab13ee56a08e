#include "renderer/graph/tiler.h"

#include <algorithm>
#include <set>

#include "renderer/format/format.h"

namespace ds::graph {
namespace {

constexpr uint32_t kMaxTexelBits = 128;  // the widest colour a tile buffer keeps per sample

std::string role_of(const GroupPlan& g, uint32_t attachment) {
    bool color = false, depth = false, resolve = false, input = false;
    for (const SubpassPlan& sp : g.subpasses) {
        auto has = [&](const std::vector<AttachmentRef>& refs) {
            return std::any_of(refs.begin(), refs.end(),
                               [&](const AttachmentRef& r) { return r.attachment == attachment; });
        };
        color |= has(sp.colors);
        resolve |= has(sp.resolves);
        input |= has(sp.inputs);
        depth |= sp.depth && sp.depth->attachment == attachment;
    }
    std::string role = depth ? "depth" : resolve ? "resolve" : color ? "colour" : "input";
    if (input && role != "input") role += "+input";
    return role;
}

// The colour attachments a tile holds: every colour or input reference that is not depth.
std::set<uint32_t> tile_colors(const GroupPlan& g, std::span<const ResourceInfo> resources) {
    std::set<uint32_t> out;
    for (const SubpassPlan& sp : g.subpasses)
        for (const auto* refs : {&sp.colors, &sp.inputs})
            for (const AttachmentRef& r : *refs)
                if (r.attachment != UINT32_MAX &&
                    !resources[g.attachments[r.attachment].resource].depth())
                    out.insert(r.attachment);
    return out;
}

TilerCondition formats_condition(const GroupPlan& g, std::span<const ResourceInfo> resources,
                                 const std::set<uint32_t>& colors) {
    TilerCondition c{"colour formats can be merged", true, ""};
    for (uint32_t a : colors) {
        const ResourceInfo& r = resources[g.attachments[a].resource];
        const uint32_t bits = format::bytes_per_texel(r.image.format) * 8;
        c.detail += (c.detail.empty() ? "" : ", ") + std::string(format::name(r.image.format)) +
                    " " + std::to_string(bits) + " bits";
        if (bits == 0 || bits > kMaxTexelBits) c.ok = false;
    }
    c.detail += c.ok ? " (each fits a tile's colour storage, <= 128 bits)"
                     : " (a format wider than 128 bits, or not a colour format)";
    return c;
}

// Merging pays only when a later subpass uses what an earlier one wrote, from tile memory.
TilerCondition sharing_condition(const GroupPlan& g, std::span<const ResourceInfo> resources) {
    TilerCondition c{"merging saves a write-out or read-back", false, ""};
    for (const SubpassDependency& d : g.dependencies) {
        for (const AttachmentRef& in : g.subpasses[d.dst].inputs) {
            c.ok = true;
            c.detail += (c.detail.empty() ? "" : ", ") +
                        resources[g.attachments[in.attachment].resource].name + ": subpass " +
                        std::to_string(d.src) + " -> input of subpass " + std::to_string(d.dst);
        }
        const auto& dst = g.subpasses[d.dst];
        const auto& src = g.subpasses[d.src];
        if (dst.depth && src.depth && dst.depth->attachment == src.depth->attachment) {
            c.ok = true;
            c.detail += std::string(c.detail.empty() ? "" : ", ") +
                        "depth kept on chip from subpass " + std::to_string(d.src) + " to " +
                        std::to_string(d.dst);
        }
    }
    if (!c.ok) c.detail = "no subpass reads what an earlier one wrote";
    return c;
}

TilerCondition count_condition(const GroupPlan& g) {
    std::set<uint32_t> unique;
    for (const SubpassPlan& sp : g.subpasses)
        for (const auto* refs : {&sp.colors, &sp.inputs})
            for (const AttachmentRef& r : *refs)
                if (r.attachment != UINT32_MAX &&
                    (!sp.depth || sp.depth->attachment != r.attachment))
                    unique.insert(r.attachment);
    return {"fewer than nine unique input and colour attachments", unique.size() < 9,
            std::to_string(unique.size()) + " (depth does not count)"};
}

TilerCondition depth_condition(const GroupPlan& g, std::span<const ResourceInfo> resources) {
    std::set<uint32_t> depths;
    bool some_without = false;
    for (const SubpassPlan& sp : g.subpasses) {
        if (sp.depth)
            depths.insert(sp.depth->attachment);
        else
            some_without = true;
    }
    const bool ok = depths.size() <= 1 && !(some_without && !depths.empty());
    std::string detail =
        depths.empty() ? "no depth attachment"
        : depths.size() == 1
            ? resources[g.attachments[*depths.begin()].resource].name +
                  (some_without ? ", but not in every subpass" : " in every subpass")
            : std::to_string(depths.size()) + " different depth attachments";
    return {"one depth attachment throughout", ok, detail};
}

TilerCondition samples_condition(const GroupPlan& g, std::span<const ResourceInfo> resources) {
    std::set<int> counts;
    for (uint32_t i = 0; i < g.attachments.size(); ++i)
        if (role_of(g, i) != "resolve")  // resolve destinations are memory, single-sample
            counts.insert(int(resources[g.attachments[i].resource].image.samples));
    std::string detail;
    for (int s : counts) detail += (detail.empty() ? "" : ", ") + std::to_string(s) + "x";
    return {"equal sample counts", counts.size() <= 1,
            detail + " (resolve destinations not counted)"};
}

}  // namespace

TilerReport tiler_report(const GroupPlan& g, std::span<const ResourceInfo> resources,
                         std::span<const bool> lazily_allocated) {
    TilerReport t;
    t.group = g.name;
    t.subpasses = uint32_t(g.subpasses.size());
    for (uint32_t i = 0; i < g.attachments.size(); ++i) {
        const GroupAttachment& a = g.attachments[i];
        const ResourceInfo& r = resources[a.resource];
        t.attachments.push_back({r.name, format::name(r.image.format), role_of(g, i),
                                 format::bytes_per_texel(r.image.format) * 8,
                                 uint32_t(r.image.samples), load_op_name(a.load),
                                 store_op_name(a.store), a.transient,
                                 i < lazily_allocated.size() && lazily_allocated[i]});
    }
    const std::set<uint32_t> colors = tile_colors(g, resources);
    for (uint32_t a : colors) {
        const ResourceInfo& r = resources[g.attachments[a].resource];
        t.bits_per_pixel += format::bytes_per_texel(r.image.format) * 8;
        t.samples = std::max(t.samples, uint32_t(r.image.samples));
    }
    t.tile_bits_per_pixel = t.bits_per_pixel * t.samples;
    t.fits_128 = t.tile_bits_per_pixel <= 128;
    t.fits_256 = t.tile_bits_per_pixel <= 256;
    t.conditions = {formats_condition(g, resources, colors), sharing_condition(g, resources),
                    count_condition(g), depth_condition(g, resources),
                    samples_condition(g, resources)};
    t.mergeable = std::all_of(t.conditions.begin(), t.conditions.end(),
                              [](const TilerCondition& c) { return c.ok; });
    std::string why;
    for (const TilerCondition& c : t.conditions)
        if (!c.ok) why += (why.empty() ? "" : "; ") + c.name + ": " + c.detail;
    t.verdict = std::string("a tiler can merge these subpasses: ") +
                (t.mergeable ? "yes" : "no (" + why + ")");
    return t;
}

}  // namespace ds::graph
