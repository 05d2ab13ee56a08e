#include "capture/tune/tune_alpha.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "renderer/common/error.h"
#include "renderer/common/quoted.h"
#include "renderer/scene/alpha_coverage.h"

namespace ds::tune {
namespace {

std::vector<int32_t> materials_named(const scene::Scene& scene, const std::string& name) {
    std::vector<int32_t> out;
    for (size_t i = 0; i < scene.materials.size(); ++i)
        if (scene.materials[i].name == name &&
            scene.materials[i].alpha_mode == scene::AlphaMode::Mask)
            out.push_back(int32_t(i));
    return out;
}

std::vector<float> coverage_of(const SurfaceSamples& s, const std::vector<int32_t>& ids) {
    std::vector<float> out(size_t(s.width) * s.height, 0.0f);
    for (int32_t id : ids) {
        const std::vector<float> c = material_coverage(s, id);
        for (size_t p = 0; p < out.size(); ++p) out[p] += c[p];
    }
    return out;
}

std::vector<InspectRequest> surface_requests(int msaa) {
    if (msaa <= 1) return {{"surface_id"}};
    std::vector<InspectRequest> out;
    for (int s = 0; s < msaa; ++s) out.push_back({"msaa_surface_id", uint32_t(s)});
    return out;
}

SurfaceSamples candidate_samples(Renderer& renderer, const scene::Scene& scene,
                                 const FrameResult& frame, int msaa) {
    const std::string name = msaa <= 1 ? "surface_id" : "msaa_surface_id";
    std::vector<const InspectedImage*> layers;
    if (frame.inspected && frame.inspected->name == name) layers.push_back(&*frame.inspected);
    for (const InspectedImage& i : frame.overlays)
        if (i.name == name) layers.push_back(&i);
    if (layers.empty()) throw Error("tune alpha: the frame has no " + name + " (prepass off?)");
    return samples_from_layers(layers, scene,
                               [&](uint32_t id) { return renderer.describe_surface(id); });
}

void compare(const std::vector<float>& ref, const std::vector<float>& cand, AlphaPoint& p) {
    for (size_t i = 0; i < ref.size(); ++i) {
        if (ref[i] <= 0.0f && cand[i] <= 0.0f) continue;
        ++p.material_pixels;
        const bool r = ref[i] >= 0.5f, c = cand[i] >= 0.5f;
        p.mismatched += r != c;
        p.covered += c;
    }
    p.coverage_error = p.material_pixels ? double(p.mismatched) / double(p.material_pixels) : 0;
}

std::vector<float> cutoffs(float step, float current) {
    std::vector<float> out;
    for (int i = 1; float(i) * step < 1.0f - 1e-6f; ++i) out.push_back(float(i) * step);
    if (std::none_of(out.begin(), out.end(),
                     [&](float c) { return std::fabs(c - current) < 1e-6f; }))
        out.push_back(current);
    std::sort(out.begin(), out.end());
    return out;
}

void pick(AlphaMaterial& m) {
    for (size_t i = 0; i < m.points.size(); ++i) {
        const AlphaPoint& p = m.points[i];
        if (!p.alpha_to_coverage && std::fabs(p.cutoff - m.cutoff) < 1e-6f) m.current = int(i);
        if (m.best < 0) {
            m.best = int(i);
            continue;
        }
        const AlphaPoint& b = m.points[size_t(m.best)];
        if (p.coverage_error < b.coverage_error ||
            (p.coverage_error == b.coverage_error &&
             std::fabs(p.cutoff - m.cutoff) < std::fabs(b.cutoff - m.cutoff)))
            m.best = int(i);
    }
}

}  // namespace

std::vector<std::string> masked_material_names(const scene::Scene& scene,
                                               const std::vector<std::string>& wanted) {
    std::set<std::string> masked;
    for (const scene::Material& m : scene.materials)
        if (m.alpha_mode == scene::AlphaMode::Mask) masked.insert(m.name);
    std::string list;
    for (const std::string& n : masked) list += (list.empty() ? "" : ", ") + quote(n);
    if (masked.empty()) throw UsageError("tune alpha: the scene has no MASK material");
    for (const std::string& w : wanted)
        if (!masked.count(w))
            throw UsageError("tune alpha: --material " + quote(w) +
                             " is no MASK material of the scene (MASK: " + list + ")");
    if (wanted.empty()) return {masked.begin(), masked.end()};
    std::set<std::string> chosen(wanted.begin(), wanted.end());
    return {chosen.begin(), chosen.end()};
}

AlphaTune tune_alpha(Renderer& renderer, const scene::Scene& scene, const scene::Camera& camera,
                     const Settings& settings, VkExtent2D size, const AlphaSweep& sweep) {
    const std::vector<std::string> names = masked_material_names(scene, sweep.materials);
    if (!(sweep.step > 0.0f && sweep.step < 1.0f)) throw UsageError("tune alpha: step out of 0..1");
    const Reference ref = render_reference(renderer, scene, camera, settings, size);
    if (ref.samples.empty()) throw UsageError("tune alpha needs the prepass (prepass=on)");
    AlphaTune t{size, sweep.cost_kind, settings.get_int("msaa"), sweep.step, ref.factor, ref.ms,
                {}};
    Settings base = scored_settings(settings);
    base.set("surface_id", "on");  // what each sample saw (it changes no pixel)
    // What the user's settings give each material (the shaders' precedence, one implementation).
    const std::vector<float> cutoffs_now = scene::effective_alpha_cutoffs(scene, settings);
    for (const std::string& name : names) {
        const std::vector<int32_t> ids = materials_named(scene, name);
        AlphaMaterial m{name, cutoffs_now[size_t(ids.front())], 0, {}, -1, -1};
        const std::vector<float> ref_cov = coverage_of(ref.samples, ids);
        for (float c : ref_cov) m.reference_covered += c >= 0.5f;
        for (float cutoff : cutoffs(sweep.step, m.cutoff))
            for (bool a2c :
                 t.msaa > 1 ? std::vector<bool>{false, true} : std::vector<bool>{false}) {
                Settings s = base;
                auto overrides = s.get_map("material_alpha_cutoff");
                overrides[name] = cutoff;
                s.set("material_alpha_cutoff", format_map(overrides));
                s.set("alpha_to_coverage", a2c ? "on" : "off");
                CandidateFrame f = render_candidate(renderer, camera, s, size, sweep.cost_kind,
                                                    sweep.timing, surface_requests(t.msaa));
                AlphaPoint p{cutoff, a2c, 0, 0, 0, 0, std::move(f.cost)};
                compare(ref_cov,
                        coverage_of(candidate_samples(renderer, scene, f.frame, t.msaa), ids), p);
                m.points.push_back(std::move(p));
            }
        pick(m);
        t.materials.push_back(std::move(m));
    }
    return t;
}

}  // namespace ds::tune
