#include "renderer/graph/dump_subpass.h"

#include <ostream>
#include <string>

#include "renderer/format/format.h"
#include "renderer/graph/dump.h"
#include "renderer/graph/names.h"

namespace ds::graph {
namespace {

std::string attachment_text(const GroupAttachment& a, const ResourceInfo& r) {
    return r.name + " " + format::name(r.image.format) + " x" + std::to_string(r.image.samples) +
           " load " + load_op_name(a.load) + " store " + store_op_name(a.store) + " " +
           layout_name(a.initial) + " -> " + layout_name(a.final) +
           (a.transient ? " transient" : "");
}

// "normals [SHADER_READ_ONLY_OPTIMAL], roughness [...]"
std::string refs_text(const std::vector<AttachmentRef>& refs, const GroupPlan& g,
                      std::span<const ResourceInfo> resources) {
    std::string text;
    for (const AttachmentRef& r : refs) {
        if (!text.empty()) text += ", ";
        text += r.attachment == UINT32_MAX ? std::string("unused")
                                           : resources[g.attachments[r.attachment].resource].name +
                                                 " [" + layout_name(r.layout) + "]";
    }
    return text;
}

nlohmann::json refs_json(const std::vector<AttachmentRef>& refs, const GroupPlan& g,
                         std::span<const ResourceInfo> resources) {
    nlohmann::json out = nlohmann::json::array();
    for (const AttachmentRef& r : refs)
        out.push_back(
            r.attachment == UINT32_MAX
                ? nlohmann::json(nullptr)
                : nlohmann::json{{"resource", resources[g.attachments[r.attachment].resource].name},
                                 {"attachment", r.attachment},
                                 {"layout", layout_name(r.layout)}});
    return out;
}

std::string masks(VkPipelineStageFlags2 stages, VkAccessFlags2 access) {
    return std::string(stage_names(stages)) + "/" + access_names(access);
}

void dump_subpass(std::ostream& out, uint32_t index, const SubpassPlan& sp, const GroupPlan& g,
                  std::span<const ResourceInfo> resources, std::span<const PassInfo> passes) {
    out << "    subpass " << index << ":";
    for (uint32_t p : sp.passes) out << " " << passes[p].name;
    out << "\n";
    if (!sp.colors.empty()) out << "      colour " << refs_text(sp.colors, g, resources) << "\n";
    if (!sp.inputs.empty()) out << "      input " << refs_text(sp.inputs, g, resources) << "\n";
    if (!sp.resolves.empty())
        out << "      resolve " << refs_text(sp.resolves, g, resources) << "\n";
    if (sp.depth)
        out << "      depth " << refs_text({*sp.depth}, g, resources)
            << (sp.depth_read_only ? " read-only" : "") << "\n";
}

}  // namespace

void dump_groups(std::ostream& out, std::span<const GroupPlan> groups,
                 std::span<const ResourceInfo> resources, std::span<const PassInfo> passes) {
    for (const GroupPlan& g : groups) {
        out << "render pass '" << g.name << "': passes " << g.first_pass + 1 << "-"
            << g.last_pass + 1 << ", " << g.subpasses.size() << " subpasses, " << g.extent.width
            << "x" << g.extent.height << "\n";
        for (size_t i = 0; i < g.attachments.size(); ++i)
            out << "    attachment " << i << ": "
                << attachment_text(g.attachments[i], resources[g.attachments[i].resource]) << "\n";
        for (uint32_t s = 0; s < g.subpasses.size(); ++s)
            dump_subpass(out, s, g.subpasses[s], g, resources, passes);
        for (const SubpassDependency& d : g.dependencies)
            out << "    dependency " << d.src << " -> " << d.dst
                << (d.by_region ? " BY_REGION " : " ") << masks(d.src_stages, d.src_access)
                << " -> " << masks(d.dst_stages, d.dst_access) << "\n";
        for (const Barrier& b : g.barriers)
            out << "    barrier before " << describe_barrier(b, resources) << "\n";
    }
}

nlohmann::json groups_json(std::span<const GroupPlan> groups,
                           std::span<const ResourceInfo> resources,
                           std::span<const PassInfo> passes) {
    nlohmann::json out = nlohmann::json::array();
    for (const GroupPlan& g : groups) {
        nlohmann::json attachments = nlohmann::json::array(), subpasses = nlohmann::json::array(),
                       dependencies = nlohmann::json::array();
        for (const GroupAttachment& a : g.attachments) {
            const ResourceInfo& r = resources[a.resource];
            attachments.push_back({{"resource", r.name},
                                   {"format", format::name(r.image.format)},
                                   {"samples", int(r.image.samples)},
                                   {"load", load_op_name(a.load)},
                                   {"store", store_op_name(a.store)},
                                   {"initial_layout", layout_name(a.initial)},
                                   {"final_layout", layout_name(a.final)},
                                   {"transient", a.transient}});
        }
        for (const SubpassPlan& sp : g.subpasses) {
            nlohmann::json names = nlohmann::json::array();
            for (uint32_t p : sp.passes) names.push_back(passes[p].name);
            subpasses.push_back({{"passes", names},
                                 {"colour", refs_json(sp.colors, g, resources)},
                                 {"input", refs_json(sp.inputs, g, resources)},
                                 {"resolve", refs_json(sp.resolves, g, resources)},
                                 {"depth", sp.depth ? refs_json({*sp.depth}, g, resources)[0]
                                                    : nlohmann::json(nullptr)},
                                 {"depth_read_only", sp.depth_read_only}});
        }
        for (const SubpassDependency& d : g.dependencies)
            dependencies.push_back({{"src", d.src},
                                    {"dst", d.dst},
                                    {"by_region", d.by_region},
                                    {"src_masks", masks(d.src_stages, d.src_access)},
                                    {"dst_masks", masks(d.dst_stages, d.dst_access)}});
        out.push_back({{"name", g.name},
                       {"attachments", attachments},
                       {"subpasses", subpasses},
                       {"dependencies", dependencies}});
    }
    return out;
}

}  // namespace ds::graph
