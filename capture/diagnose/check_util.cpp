// What the checks share: naming surfaces (with glTF pointers), the frame's skip reasons, the
// read-back images and the Z-fight pairs' pixels.
#include <cmath>

#include "capture/diagnose/checks.h"
#include "renderer/passes/zfight.h"
#include "renderer/settings/frame_knobs.h"

namespace ds::diagnose {

FindingSurface surface_of(const scene::Scene& scene, uint32_t instance) {
    const SurfaceName name = scene.instance_name(instance);
    const int node = scene.instances.at(instance).gltf_node;
    return {name.mesh, name.material, name.node,
            node >= 0 ? "/nodes/" + std::to_string(node) : std::string()};
}

FindingSurface surface_named(const scene::Scene& scene, const SurfaceName& name) {
    for (uint32_t i = 0; i < scene.instances.size(); ++i)
        if (scene.instance_name(i) == name) return surface_of(scene, i);
    return {name.mesh, name.material, name.node, ""};
}

std::vector<FindingSurface> material_surfaces(const scene::Scene& scene, uint32_t material,
                                              size_t max) {
    std::vector<FindingSurface> out;
    for (uint32_t i = 0; i < scene.instances.size() && out.size() < max; ++i)
        if (scene.meshes.at(scene.instances[i].mesh).material == material)
            out.push_back(surface_of(scene, i));
    return out;
}

std::string label(const FindingSurface& s) {
    if (!s.node.empty() && !s.node.starts_with("node ")) return s.node;
    return s.mesh + " (" + s.material + ")";
}

std::vector<FindingSurface> group_surfaces(const scene::Scene& scene, uint32_t first,
                                           uint32_t count, size_t max) {
    std::vector<FindingSurface> out;
    for (uint32_t i = first; i < first + count && out.size() < max; ++i)
        out.push_back(surface_of(scene, i));
    return out;
}

std::string group_label(const scene::Scene& scene, uint32_t first, uint32_t count) {
    if (count == 1) return label(surface_of(scene, first));
    return "mesh " + surface_of(scene, first).mesh + " (" + std::to_string(count) + " instances)";
}

std::optional<std::string> frame_skip_reason(const FrameResult& frame, std::string_view pass,
                                             std::string_view knob) {
    const std::string prefix = std::string(pass) + ": skipped (";
    for (const std::string& s : frame.skipped)
        if (s.starts_with(prefix) && s.ends_with(")"))
            return s.substr(prefix.size(), s.size() - prefix.size() - 1);
    for (const std::string& k : frame.subpass_turned_off)
        if (k == knob) return "render_path=subpass: the per-pass diagnostics do not run on it";
    return std::nullopt;
}

const PassResult* pass_named(const FrameResult& frame, std::string_view name) {
    for (const PassResult& p : frame.passes)
        if (p.name == name && p.role == graph::PassRole::Frame) return &p;
    return nullptr;
}

std::vector<std::vector<uint32_t>> pair_pixels(const ZfightResult& z) {
    std::vector<std::vector<uint32_t>> out(z.pairs.size());
    for (const ZfightHit& hit : z.hits)
        if (hit.pair < out.size()) out[hit.pair].push_back(hit.pixel);
    for (auto& pixels : out) normalise_pixels(pixels);
    return out;
}

bool is_decal_pair(const scene::Scene& scene, const SurfaceName& a, const SurfaceName& b) {
    for (const scene::Decal& d : scene.decals) {
        const SurfaceName overlay = scene.instance_name(d.instance);
        const SurfaceName base = scene.instance_name(d.base);
        if ((overlay == a && base == b) || (overlay == b && base == a)) return true;
    }
    return false;
}

std::string depth_label(const Settings& settings) {
    return knob_value(settings, knobs::kDepthFormat) +
           (knob_value(settings, knobs::kReverseZ) ? " reverse-Z" : " forward-Z");
}

std::vector<uint32_t> pixels_where(const InspectedImage& image, float value) {
    std::vector<uint32_t> out;
    const size_t n = size_t(image.width) * image.height;
    for (size_t i = 0; i < n && i * 4 < image.texels.size(); ++i)
        if (std::fabs(image.texels[i * 4] - value) < 0.5f) out.push_back(uint32_t(i));
    return out;
}

}  // namespace ds::diagnose
