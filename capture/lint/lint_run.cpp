// lint_scene: every check of capture/lint/ in order, the findings ranked.
#include "capture/lint/checks.h"

namespace ds::lint {
namespace {

using Check = void (*)(const Input&, Output&);
constexpr Check kChecks[] = {check_surface_pairs, check_degenerate,  check_decals,
                             check_alpha_mode,    check_depth_range, check_overdraw,
                             check_mesh_overdraw};

}  // namespace

std::vector<int64_t> first_instances(const scene::Scene& scene) {
    std::vector<int64_t> first(scene.meshes.size(), -1);
    for (uint32_t i = 0; i < scene.instances.size(); ++i)
        if (first.at(scene.instances[i].mesh) < 0) first[scene.instances[i].mesh] = i;
    return first;
}

Report lint_scene(const Input& in) {
    Report r;
    r.scene = in.scene.name;
    r.source = in.scene.source;
    r.views = in.views;
    for (const auto& [name, value] : in.settings.values()) r.settings.push_back({name, value});
    if (!in.views.empty()) r.depth = depth_config(in.settings, in.views.front().camera);
    Output out;
    for (const Check check : kChecks) check(in, out);
    diagnose::rank(out.findings);
    r.findings = std::move(out.findings);
    r.checks = std::move(out.ran);
    r.skipped = std::move(out.skipped);
    r.images = std::move(out.images);
    r.frames = out.frames;
    return r;
}

}  // namespace ds::lint
