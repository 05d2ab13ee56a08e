#include "renderer/graph/dump_json.h"

#include "renderer/format/format.h"
#include "renderer/graph/dump.h"
#include "renderer/graph/dump_subpass.h"
#include "renderer/graph/names.h"

namespace ds::graph {
namespace {

nlohmann::json resource_json(const ResourceInfo& r) {
    nlohmann::json j = {{"name", r.name}, {"lifetime", lifetime_name(r.lifetime)}};
    if (r.is_image) {
        j["kind"] = "image";
        j["format"] = format::name(r.image.format);
        j["width"] = r.extent.width;
        j["height"] = r.extent.height;
        j["size"] = r.image.size.is_relative()
                        ? nlohmann::json{{"output_scale", r.image.size.scale}}
                        : nlohmann::json("fixed");
        j["samples"] = int(r.image.samples);
        j["mips"] = r.image.mip_levels;
        j["semantic"] = semantic_name(r.image.semantic);
        j["usage"] = image_usage_names(r.usage);
        if (r.history == HistoryRole::Previous)
            j["history"] = r.history_valid ? "previous (valid)" : "previous (invalid)";
        if (r.history == HistoryRole::Current) j["history"] = "current";
    } else {
        j["kind"] = "buffer";
        j["bytes"] = r.size;
        j["usage"] = buffer_usage_names(r.usage);
    }
    return j;
}

nlohmann::json barriers_json(std::span<const Barrier> barriers,
                             std::span<const ResourceInfo> resources) {
    nlohmann::json out = nlohmann::json::array();
    for (const Barrier& b : barriers) {
        nlohmann::json j = {
            {"resource", resources[b.resource].name},
            {"src", std::string(stage_names(b.src_stages)) + "/" + access_names(b.src_access)},
            {"dst", std::string(stage_names(b.dst_stages)) + "/" + access_names(b.dst_access)}};
        if (b.is_image) {
            j["old_layout"] = layout_name(b.old_layout);
            j["new_layout"] = layout_name(b.new_layout);
        }
        out.push_back(std::move(j));
    }
    return out;
}

nlohmann::json pass_json(const PassInfo& pass, const PassPlan& plan,
                         std::span<const ResourceInfo> resources) {
    nlohmann::json reads = nlohmann::json::array(), writes = nlohmann::json::array();
    for (const AccessInfo& a : pass.accesses) {
        nlohmann::json j = {{"resource", resources[a.resource].name},
                            {"access", access_name(a.access)}};
        (is_write(a.access) ? writes : reads).push_back(std::move(j));
    }
    nlohmann::json j = {{"name", pass.name},
                        {"kind", pass_kind_name(pass.kind)},
                        {"role", pass_role_name(pass.role)},
                        {"barriers", barriers_json(plan.barriers, resources)},
                        {"reads", reads},
                        {"writes", writes}};
    if (!pass.group.empty()) j["subpass"] = {{"group", pass.group}, {"index", pass.subpass}};
    return j;
}

}  // namespace

nlohmann::json graph_json(VkExtent2D output, std::span<const ResourceInfo> resources,
                          std::span<const PassInfo> passes, const BarrierPlan& plan,
                          std::span<const GroupPlan> groups) {
    nlohmann::json res = nlohmann::json::array(), out_passes = nlohmann::json::array();
    for (const ResourceInfo& r : resources) res.push_back(resource_json(r));
    const PassPlan not_compiled;
    for (size_t i = 0; i < passes.size(); ++i)
        out_passes.push_back(pass_json(
            passes[i], i < plan.passes.size() ? plan.passes[i] : not_compiled, resources));
    return {{"output", {{"width", output.width}, {"height", output.height}}},
            {"resources", res},
            {"passes", out_passes},
            {"end_of_frame", barriers_json(plan.final_barriers, resources)},
            {"subpass_groups", groups_json(groups, resources, passes)}};
}

}  // namespace ds::graph
