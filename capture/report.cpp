#include "capture/report.h"

#include <algorithm>
#include <sstream>
#include <string>

#include "capture/file_output.h"
#include "capture/replay_info.h"
#include "capture/tiler_json.h"
#include "renderer/common/error.h"
#include "renderer/common/surface_json.h"
#include "renderer/common/version.h"
#include "renderer/format/format.h"

namespace ds::capture {

nlohmann::json scene_summary(const scene::Scene& s) {
    size_t by_mode[3] = {0, 0, 0};
    for (const auto& m : s.materials) ++by_mode[size_t(m.alpha_mode)];
    return {
        {"name", s.name},
        {"source", s.source},
        {"gltf_meshes", s.gltf_mesh_count},
        {"meshes", s.meshes.size()},
        {"materials",
         {{"total", s.materials.size()},
          {"opaque", by_mode[0]},
          {"mask", by_mode[1]},
          {"blend", by_mode[2]}}},
        {"textures", s.textures.size()},
        {"instances", s.instances.size()},
        {"draw_groups", s.draw_groups.size()},
        {"triangles", s.triangle_count()},
        {"warnings", s.warnings},
    };
}

nlohmann::json counters_note(const DeviceInfo& device) {
    return {
        {"stats", "the device's pipeline statistics; fragment_shader_invocations: " +
                      (device.fragment_statistic.empty() ? std::string("not described")
                                                         : device.fragment_statistic)},
        {"shaded_fragments",
         "exact: fragments that ran the fragment shader, counted per pixel by the shaders on "
         "entry (count_fragments=on); with early fragment tests those that passed the depth "
         "test, for a pipeline with discard (late depth test) every fragment it rasterized"},
        {"discarded_fragments",
         "exact: of those, the fragments the alpha test discarded (count_fragments=on)"},
        {"rasterized_fragments",
         "exact: fragments the pass's draws rasterized, whatever the depth test or a discard "
         "made of them (depth complexity), from a measurement draw with the depth test off "
         "(count_fragments=on)"},
        {"quad_overdraw",
         "exact: 2x2 quads that ran the fragment shader with at least one live lane, their "
         "lanes (4 each, helpers included) and lanes per shaded fragment (count_fragments=on, "
         "devices with quad subgroup operations in fragment shaders)"},
    };
}

nlohmann::json passes_json(const std::vector<PassResult>& passes,
                           const PassMeasurements& measured) {
    nlohmann::json out = nlohmann::json::array();
    for (size_t i = 0; i < passes.size(); ++i) {
        nlohmann::json pass = {{"name", passes[i].name},
                               {"kind", graph::pass_role_name(passes[i].role)}};
        pass.update(measured(i));
        // Geometry passes: each pipeline's early-Z verdict and its draws (issue 11 part 3), and
        // whether it has a fragment stage at all (issue 14: the Z-only prepass has none).
        if (!passes[i].pipelines.empty()) {
            nlohmann::json pipelines = nlohmann::json::array();
            for (const PipelineReport& r : passes[i].pipelines)
                pipelines.push_back({{"name", r.name},
                                     {"early_z", r.early_z},
                                     {"draws", r.draws},
                                     {"fragment_stage", r.fragment_stage}});
            pass["pipelines"] = std::move(pipelines);
        }
        out.push_back(std::move(pass));
    }
    return out;
}

namespace {

nlohmann::json settings_json(const Settings& settings) {
    nlohmann::json json = nlohmann::json::object();  // {} even when there are none
    for (const auto& [name, value] : settings.values()) json[name] = value;
    return json;
}

// One frame's measurements of a pass: GPU time, the device's statistics, the exact count.
nlohmann::json frame_pass_measurements(const PassResult& p) {
    nlohmann::json json = {
        {"gpu_ms", p.gpu_ms},
        {"stats",
         {{"vertex_shader_invocations", p.vertex_shader_invocations},
          {"fragment_shader_invocations", p.fragment_shader_invocations},
          {"clipping_primitives", p.clipping_primitives}}},
    };
    if (p.rasterized_fragments) json["rasterized_fragments"] = *p.rasterized_fragments;
    if (p.shaded_fragments) json["shaded_fragments"] = *p.shaded_fragments;
    if (p.discarded_fragments) json["discarded_fragments"] = *p.discarded_fragments;
    if (p.quads) {
        const uint64_t lanes = 4 * *p.quads;
        const uint64_t shaded = p.shaded_fragments.value_or(0);
        json["quad_overdraw"] = {
            {"quads", *p.quads},
            {"lanes", lanes},
            {"lanes_per_shaded", shaded ? double(lanes) / double(shaded) : 0.0}};
    } else if (p.shaded_fragments) {  // counted, but the device cannot count quads
        json["quad_overdraw"] = "unsupported on this device";
    }
    return json;
}

nlohmann::json msaa_json(const MsaaResult& msaa) {
    nlohmann::json json = {{"samples", msaa.samples}};
    if (msaa.samples > 1) {
        json["depth_resolve"] = msaa.depth_resolve;
        if (msaa.edge_pixels) json["edge_pixels"] = *msaa.edge_pixels;
    }
    return json;
}

// A float as its shortest text reads (0.1f is 0.1, not 0.100000001), as the registry writes.
double plain(float v) {
    std::ostringstream out;
    out.precision(7);
    out << v;
    return std::stod(out.str());
}

// The coplanar overlays the importer classified (scene::Scene::decals) and the surfaces they
// lie on, and whether this frame drew them in the decals pass (decal_pass=on) or like any
// surface.
nlohmann::json decals_json(const scene::Scene& s, const FrameResult& f) {
    nlohmann::json overlays = nlohmann::json::array();
    for (const scene::Decal& d : s.decals)
        overlays.push_back(
            {{"overlay", surface_json(s.instance_name(d.instance))},
             {"base", surface_json(s.instance_name(d.base))},
             {"alpha_mode", scene::to_string(s.instance_material(d.instance).alpha_mode)}});
    nlohmann::json buried = nlohmann::json::array();
    for (const scene::BuriedOverlay& b : s.buried)
        buried.push_back({{"overlay", surface_json(s.instance_name(b.instance))},
                          {"base", surface_json(s.instance_name(b.base))},
                          {"gap", b.gap}});
    const bool pass = std::any_of(f.passes.begin(), f.passes.end(),
                                  [](const PassResult& p) { return p.name == "decals"; });
    return {{"overlays", overlays}, {"buried", buried}, {"decals_pass", pass}};
}

nlohmann::json depth_json(const DepthResult& depth) {
    return {{"format", format::name(depth.format)},
            {"znear", plain(depth.znear)},
            {"zfar", plain(depth.zfar)},
            {"reverse_z", depth.reverse_z}};
}

}  // namespace

nlohmann::json frame_report(const ReportInput& in) {
    const FrameResult& f = in.frame;
    nlohmann::json json = {
        {"tool", "depthscope"},
        {"version", version()},
        {"device",
         {{"name", in.device.name}, {"driver", in.device.driver}, {"api", in.device.api_version}}},
        {"scene", scene_summary(in.scene)},
        {"size", {{"width", f.width}, {"height", f.height}}},
        {"settings", settings_json(in.settings)},
        {"frame", {{"gpu_ms", f.gpu_ms}, {"cpu_ms", f.cpu_ms}}},
        {"validation_messages", in.validation_messages},
        {"passes",
         passes_json(f.passes, [&](size_t i) { return frame_pass_measurements(f.passes[i]); })},
        {"counters", counters_note(in.device)},
        {"skipped", f.skipped},
        {"msaa", msaa_json(f.msaa)},
        {"tiler", tiler_json(f.tiler, f.subpass_turned_off, in.settings)},
    };
    if (f.depth) json["depth"] = depth_json(*f.depth);
    json["decals"] = decals_json(in.scene, f);
    // Left out when not counted, so that a reader never takes "not counted" for zero.
    if (f.covered_pixels) json["coverage"] = {{"covered_pixels", *f.covered_pixels}};
    // Each pass's own sections (hiz, zfight, equal_check, draws, ...), in pass order.
    f.slots.write_report(f, json);
    if (in.advice) json["advice"] = advice_json(*in.advice);
    if (in.camera) json["replay"] = replay_json(in.scene, *in.camera, in.settings);
    if (in.graph) json["graph"] = *in.graph;
    return json;
}

void write_json(const std::filesystem::path& path, const nlohmann::json& json) {
    write_new_file(path, json.dump(2) + '\n');
}

void write_json_atomically(std::string_view option, const std::filesystem::path& path,
                           const nlohmann::json& json) {
    write_file_atomically(option, path, json.dump(2) + '\n');
}

}  // namespace ds::capture
