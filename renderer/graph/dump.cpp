#include "renderer/graph/dump.h"

#include <sstream>

#include "renderer/format/format.h"
#include "renderer/graph/dump_subpass.h"
#include "renderer/graph/names.h"

namespace ds::graph {
namespace {

std::string size_text(const ResourceInfo& r) {
    std::ostringstream out;
    out << r.extent.width << "x" << r.extent.height;
    if (r.image.size.is_relative())
        out << " (output x" << r.image.size.scale << ")";
    else
        out << " (fixed)";
    return out.str();
}

void dump_resource(std::ostream& out, const ResourceInfo& r) {
    out << "  " << r.name << ": ";
    if (r.is_image) {
        out << "image " << format::name(r.image.format) << " " << size_text(r) << " samples "
            << int(r.image.samples) << " mips " << r.image.mip_levels << " "
            << semantic_name(r.image.semantic) << " " << lifetime_name(r.lifetime);
        if (r.history == HistoryRole::Previous)
            out << " previous (" << (r.history_valid ? "valid" : "invalid") << ")";
        if (r.history == HistoryRole::Current) out << " current";
        out << " usage " << image_usage_names(r.usage);
    } else {
        out << "buffer " << r.size << " bytes " << lifetime_name(r.lifetime) << " usage "
            << buffer_usage_names(r.usage);
    }
    if (r.lifetime == Lifetime::External) {
        out << " initial " << (r.is_image ? std::string(layout_name(r.initial.layout)) + " " : "")
            << stage_names(r.initial.write_stages | r.initial.read_stages);
        if (r.final)
            out << " final " << (r.is_image ? std::string(layout_name(r.final->layout)) + " " : "")
                << stage_names(r.final->stages) << "/" << access_names(r.final->access);
    }
    out << "\n";
}

// "renders 64x48: colour hdr (clear, store), depth depth (load, none, read-only)".
void dump_rendering(std::ostream& out, const RenderingPlan& r,
                    std::span<const ResourceInfo> resources) {
    out << "     renders " << r.extent.width << "x" << r.extent.height;
    const char* separator = ":";
    auto attachment = [&](const char* what, const RenderingAttachment& a, bool read_only) {
        out << separator << " " << what << " ";
        separator = ",";
        if (a.resource == kNoResource) {
            out << "unused";
            return;
        }
        out << resources[a.resource].name << " (" << load_op_name(a.load) << ", "
            << (a.store == VK_ATTACHMENT_STORE_OP_NONE ? "none" : store_op_name(a.store))
            << (read_only ? ", read-only" : "") << ")";
        if (a.resolve != kNoResource) out << " -> " << resources[a.resolve].name;
    };
    for (const RenderingAttachment& c : r.colors) attachment("colour", c, false);
    if (r.depth) attachment("depth", *r.depth, r.depth->store == VK_ATTACHMENT_STORE_OP_NONE);
    if (r.colors.empty() && !r.depth) out << ": no attachments";
    out << "\n";
}

void dump_pass(std::ostream& out, size_t index, const PassInfo& pass, const PassPlan& plan,
               std::span<const ResourceInfo> resources) {
    out << "  " << index + 1 << ". " << pass.name << " (" << pass_kind_name(pass.kind);
    if (pass.role != PassRole::Frame) out << ", " << pass_role_name(pass.role);
    if (!pass.group.empty()) out << ", subpass " << pass.subpass << " of '" << pass.group << "'";
    out << ")\n";
    for (const Barrier& b : plan.barriers)
        out << "     barrier " << describe_barrier(b, resources) << "\n";
    for (const AccessInfo& a : pass.accesses) {
        const ResourceInfo& r = resources[a.resource];
        out << "     " << (is_write(a.access) ? "write " : "read ") << r.name << ": "
            << access_name(a.access);
        const Use use = describe(a.access, a.shader, r.depth());
        if (use.stages &
            (VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT |
             VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT))
            out << " (" << shader_name(a.shader) << ")";
        for (const PassUse& u : plan.uses)
            if (u.resource == a.resource && r.is_image)
                out << " [" << layout_name(u.use.layout) << "]";
        out << "\n";
    }
}

}  // namespace

std::string describe_barrier(const Barrier& b, std::span<const ResourceInfo> resources) {
    std::ostringstream out;
    out << resources[b.resource].name << ": ";
    if (b.is_image)
        out << layout_name(b.old_layout) << " -> " << layout_name(b.new_layout) << ", ";
    else
        out << "buffer, ";
    out << stage_names(b.src_stages) << "/" << access_names(b.src_access) << " -> "
        << stage_names(b.dst_stages) << "/" << access_names(b.dst_access);
    return out.str();
}

std::string dump_graph(VkExtent2D output, std::span<const ResourceInfo> resources,
                       std::span<const PassInfo> passes, const BarrierPlan& plan,
                       std::span<const GroupPlan> groups,
                       std::span<const RenderingPlan> renderings) {
    std::ostringstream out;
    out << "render graph: output " << output.width << "x" << output.height << ", " << passes.size()
        << " passes, " << resources.size() << " resources\n";
    out << "resources:\n";
    for (const ResourceInfo& r : resources) dump_resource(out, r);
    out << "passes:\n";
    const PassPlan not_compiled;  // before compile(): declarations without barriers
    for (size_t i = 0; i < passes.size(); ++i) {
        dump_pass(out, i, passes[i], i < plan.passes.size() ? plan.passes[i] : not_compiled,
                  resources);
        if (i < renderings.size() && passes[i].renders() && passes[i].group.empty())
            dump_rendering(out, renderings[i], resources);
    }
    if (!plan.final_barriers.empty()) {
        out << "end of frame:\n";
        for (const Barrier& b : plan.final_barriers)
            out << "     barrier " << describe_barrier(b, resources) << "\n";
    }
    if (!groups.empty()) {
        out << "subpass groups:\n";
        dump_groups(out, groups, resources, passes);
    }
    return out.str();
}

}  // namespace ds::graph
