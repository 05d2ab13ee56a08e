#include "capture/diagnose/diagnose_run.h"

#include <algorithm>
#include <optional>

#include "capture/diagnose/checks.h"
#include "renderer/common/error.h"
#include "renderer/device_info.h"
#include "renderer/passes/clear_counts.h"
#include "renderer/passes/depth_precision.h"
#include "renderer/passes/draw_counts.h"
#include "renderer/passes/equal_check.h"
#include "renderer/passes/zfight.h"
#include "renderer/settings/frame_knobs.h"

namespace ds::diagnose {
namespace {

using Check = void (*)(const CheckInput&, CheckOutput&);
constexpr Check kChecks[] = {check_zfight, check_decals, check_equal,     check_early_z,
                             check_draws,  check_advice, check_precision, check_alpha_coverage};

// The images the checks read, inspected by the measuring frame (a name the frame lacks is
// left out of FrameResult::overlays, and the check says why it has none).
const std::vector<InspectRequest> kInspected = {
    {"equal_check", 0}, {"depth_precision", 0}, {"forward_rasterized", 0}};

// The advisor's result and a plain frame of the user's prepass setting it rendered.
struct AdvisorRun {
    std::optional<capture::Advice> advice;
    std::optional<FrameResult> plain;
    std::string skipped;
    uint32_t frames = 0;
};

AdvisorRun run_advisor(Renderer& renderer, const scene::Camera& camera, const Settings& settings,
                       VkExtent2D size, const DeviceInfo& device) {
    AdvisorRun run;
    if (knob_value(settings, knobs::kRenderPath) == "subpass") {
        run.skipped = "render_path=subpass: count_fragments does not run on it";
        return run;
    }
    if (!device.fragment_counts) {
        run.skipped = "needs fragmentStoresAndAtomics (exact fragment counts), which " +
                      device.name + " does not offer";
        return run;
    }
    const bool prepass = knob_value(settings, knobs::kPrepass);
    const capture::RenderFrame render = [&](const Settings& s) {
        ++run.frames;
        FrameResult f = renderer.render(
            camera, s, {.width = size.width, .height = size.height, .read_back = ReadBack::No});
        if (!run.plain && !knob_value(s, passes::ClearCountsPass::kKnob) &&
            knob_value(s, knobs::kPrepass) == prepass)
            run.plain = f;  // its first plain frame: the pipelines are the same in all
        return f;
    };
    run.advice = capture::advise(capture::measure_advice(settings, render, kAdviceRun));
    return run;
}

// "name=value" for every knob `measuring` changed.
std::vector<std::string> added_knobs(const Settings& measuring, const Settings& settings) {
    std::vector<std::string> out;
    for (const std::string& name : measuring.diff(settings))
        out.push_back(name + "=" + measuring.get(name));
    return out;
}

// The checks' skipped list, where the device already said why a detector cannot run.
std::vector<SkippedDetector> merge_skipped(std::vector<SkippedDetector> device,
                                           const std::vector<SkippedDetector>& checks) {
    for (const SkippedDetector& s : checks) {
        const bool known = std::any_of(device.begin(), device.end(),
                                       [&](const auto& d) { return d.detector == s.detector; });
        if (!known) device.push_back(s);
    }
    return device;
}

}  // namespace

Settings with_measurement_knobs(const Settings& settings, const DeviceInfo& device,
                                std::vector<SkippedDetector>& skipped) {
    Settings m = settings;
    set_knob(m, passes::DepthPrecisionPass::kKnob, "on");
    if (!device.fragment_counts) {
        const std::string why =
            "needs fragmentStoresAndAtomics, which " + device.name + " does not offer";
        for (const char* d : {"zfight", "equal_check", "draws"}) skipped.push_back({d, why});
        return m;
    }
    set_knob(m, passes::ClearCountsPass::kKnob, "on");
    set_knob(m, passes::ZfightPass::kKnob, "on");
    set_knob(m, passes::EqualCheckPass::kKnob, "on");
    if (device.draw_counts)
        set_knob(m, passes::DrawCountsPass::kKnob, "on");
    else
        skipped.push_back(
            {"draws", "count_draws needs occlusionQueryPrecise and geometryShader, which " +
                          device.name + " does not offer"});
    return m;
}

Diagnosis diagnose(Renderer& renderer, const scene::Scene& scene, const scene::Camera& camera,
                   const Settings& settings, VkExtent2D size) {
    Diagnosis d;
    d.scene = scene.name;
    d.scene_source = scene.source;
    d.camera = camera;
    d.width = size.width;
    d.height = size.height;
    for (const auto& [name, value] : settings.values()) d.settings.push_back({name, value});

    const DeviceInfo device = device_info(renderer);
    std::vector<SkippedDetector> device_skips;
    const Settings measuring = with_measurement_knobs(settings, device, device_skips);
    d.measurement_knobs = added_knobs(measuring, settings);
    const FrameResult measured = renderer.render(camera, measuring,
                                                 {.width = size.width,
                                                  .height = size.height,
                                                  .read_back = ReadBack::No,
                                                  .inspect = kInspected});
    const AdvisorRun advisor = run_advisor(renderer, camera, settings, size, device);
    d.frames = 1 + advisor.frames;

    const CheckInput in{.scene = scene,
                        .settings = settings,
                        .measured = measured,
                        .plain = advisor.plain ? &*advisor.plain : nullptr,
                        .advice = advisor.advice ? &*advisor.advice : nullptr,
                        .advice_skipped = advisor.skipped,
                        .width = size.width,
                        .height = size.height};
    CheckOutput out;
    for (const Check check : kChecks) check(in, out);
    rank(out.findings);
    d.findings = std::move(out.findings);
    d.detectors = std::move(out.ran);
    d.skipped = merge_skipped(std::move(device_skips), out.skipped);
    return d;
}

}  // namespace ds::diagnose
