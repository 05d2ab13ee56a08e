// OVERDRAW (warning): from each view (lint.h: the scene's cameras, else "fit inside"), the
// fragments the colour passes rasterize per pixel the scene covers, counted exactly
// (count_fragments) in a frame without the prepass, so that every layer of geometry a pixel
// has is counted once whatever the draw order: above Thresholds::overdraw it is a warning
// naming the draws that shade the most (count_draws). The worst views' rasterized counts are
// written as heat-map PNGs (view/heat.h) when Input::images is set.
#include <algorithm>
#include <cmath>

#include "capture/diagnose/checks.h"
#include "capture/diagnose/finding_json.h"
#include "capture/file_output.h"
#include "capture/image_writer.h"
#include "capture/layer_capture_data.h"
#include "capture/lint/checks.h"
#include "renderer/device_info.h"
#include "renderer/passes/clear_counts.h"
#include "renderer/passes/draw_counts.h"
#include "renderer/renderer.h"
#include "renderer/settings/frame_knobs.h"

namespace ds::lint {
namespace {

constexpr size_t kMaxViews = 8;    // views rendered per scene (the first ones)
constexpr size_t kMaxImages = 3;   // the worst views over the threshold
constexpr size_t kNamedDraws = 3;  // draws a finding names
const char* const kCountImage = "forward_rasterized";

struct ViewOverdraw {
    size_t view = 0;
    uint64_t rasterized = 0, covered = 0;
    double ratio = 0.0;
    std::vector<std::pair<uint64_t, uint32_t>> draws;  // (shaded fragments, draw group)
    std::optional<InspectedImage> counts;
};

Settings overdraw_settings(const Settings& user, bool draw_counts) {
    Settings s = user;
    set_knob(s, knobs::kPrepass, "off");
    set_knob(s, knobs::kRenderPath, "dynamic");
    set_knob(s, knobs::kMsaa, "1");
    set_knob(s, passes::ClearCountsPass::kKnob, "on");
    if (draw_counts) set_knob(s, passes::DrawCountsPass::kKnob, "on");
    return s;
}

ViewOverdraw measure_view(const Input& in, const Settings& s, size_t v) {
    const FrameResult f = in.renderer->render(in.views[v].camera, s,
                                              {.width = in.width,
                                               .height = in.height,
                                               .read_back = ReadBack::No,
                                               .inspect = {{kCountImage, 0}}});
    ViewOverdraw o;
    o.view = v;
    for (const PassResult& p : f.passes)
        if (p.role == graph::PassRole::Frame && !p.name.starts_with("shadow"))
            o.rasterized += p.rasterized_fragments.value_or(0);
    o.covered = f.covered_pixels.value_or(0);
    o.ratio = o.covered ? double(o.rasterized) / double(o.covered) : 0.0;
    for (const DrawReport& d : passes::draws_of(f).draws) {
        uint64_t shaded = 0;
        for (const auto& [pass, n] : d.shaded_fragments)
            if (!pass.starts_with("shadow")) shaded += n;
        if (shaded) o.draws.push_back({shaded, d.group});
    }
    std::sort(o.draws.rbegin(), o.draws.rend());
    if (const InspectedImage* image = f.image(kCountImage)) o.counts = *image;
    return o;
}

Finding overdraw_finding(const Input& in, const ViewOverdraw& o) {
    const View& v = in.views[o.view];
    Finding f;
    f.code = "OVERDRAW";
    f.severity = Severity::Warning;
    f.detector = "overdraw";
    f.pointer = v.pointer;
    f.magnitude = {std::round(o.ratio * 100.0) / 100.0, "x"};
    f.message = "overdraw " + diagnose::grouped(f.magnitude.value) + " from " + v.name + ": " +
                diagnose::grouped(double(o.rasterized)) + " fragments rasterized for " +
                diagnose::grouped(double(o.covered)) + " covered px (threshold " +
                g3(in.thresholds.overdraw) + ")";
    std::string most;
    for (size_t i = 0; i < o.draws.size() && i < kNamedDraws; ++i) {
        const scene::DrawGroup& g = in.scene.draw_groups.at(o.draws[i].second);
        f.surfaces.push_back(diagnose::surface_of(in.scene, g.first_instance));
        most += (i ? ", " : "") +
                diagnose::group_label(in.scene, g.first_instance, g.instance_count) + " " +
                diagnose::grouped(double(o.draws[i].first));
    }
    if (!most.empty()) f.message += "; most shaded: " + most;
    f.fix =
        "keep the prepass on for this content (prepass=on), and occlusion-cull or merge the "
        "layers the most-shaded draws stack";
    return f;
}

// The view's rasterized counts as a heat map: 0 black, white at twice the threshold or the
// largest count, whichever is more (a fixed scale, so views compare).
std::string write_heat(const Input& in, const ViewOverdraw& o, size_t rank) {
    const InspectedImage& c = *o.counts;
    std::vector<uint32_t> counts(size_t(c.width) * c.height, 0);
    uint32_t largest = uint32_t(std::ceil(2.0 * in.thresholds.overdraw));
    for (size_t i = 0; i < counts.size() && i * 4 < c.texels.size(); ++i) {
        counts[i] = uint32_t(std::max(0.0f, c.texels[i * 4]));
        largest = std::max(largest, counts[i]);
    }
    const std::string name = in.scene.name + ".overdraw." + std::to_string(rank + 1) + ".png";
    const std::filesystem::path path = in.images / name;
    capture::write_file_atomically(
        "--images", path,
        capture::encode_png_rgba8(path, c.width, c.height,
                                  capture::count_heat_rgba(counts, largest)));
    return name;
}

}  // namespace

void check_overdraw(const Input& in, Output& out) {
    if (!in.renderer) return out.skip("overdraw", "no renderer (the device is not used)");
    const DeviceInfo device = device_info(*in.renderer);
    if (!device.fragment_counts)
        return out.skip("overdraw",
                        "needs fragmentStoresAndAtomics (exact fragment counts), "
                        "which " +
                            device.name + " does not offer");
    out.ran.push_back("overdraw");
    const Settings s = overdraw_settings(in.settings, device.draw_counts);
    std::vector<ViewOverdraw> over;
    for (size_t v = 0; v < in.views.size() && v < kMaxViews; ++v) {
        ViewOverdraw o = measure_view(in, s, v);
        ++out.frames;
        if (o.ratio > in.thresholds.overdraw) over.push_back(std::move(o));
    }
    if (in.views.size() > kMaxViews)
        out.skip("overdraw",
                 "views beyond the first " + std::to_string(kMaxViews) + " not rendered");
    std::stable_sort(over.begin(), over.end(),
                     [](const auto& a, const auto& b) { return a.ratio > b.ratio; });
    for (size_t i = 0; i < over.size(); ++i) {
        Finding f = overdraw_finding(in, over[i]);
        if (!in.images.empty() && i < kMaxImages && over[i].counts) {
            out.images.push_back(write_heat(in, over[i], i));
            f.message += " (heat map: " + out.images.back() + ")";
        }
        out.findings.push_back(std::move(f));
    }
}

}  // namespace ds::lint
