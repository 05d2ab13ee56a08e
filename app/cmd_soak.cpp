// bench --soak SECONDS: one renderer left running for SECONDS over every built-in scene (and
// --scene's file), sizes, msaa counts, prepass on / off and the diagnostics (soak_cycle),
// sampling resident memory at the end of each cycle; fails when it grew after warm-up (the
// first cycle) beyond the tolerance (judge_rss) or, with --validate, when the validation layer
// reports anything (teardown's leak check at vkDestroyDevice included).
#include <chrono>
#include <cstdio>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "app/exit_code.h"
#include "app/scene_load.h"
#include "app/soak.h"
#include "capture/file_output.h"
#include "capture/report.h"
#include "renderer/common/error.h"
#include "renderer/device_info.h"
#include "renderer/renderer.h"
#include "renderer/scene/builtin/builtin.h"
#include "renderer/scene/loader.h"
#include "renderer/settings/frame_knobs.h"

namespace ds::app {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

void check_soak_usage(const Options& o) {
    if (!o.matrix.empty() || o.ui || o.advise)
        throw UsageError("--soak picks its own combinations: drop --matrix, --ui and --advise");
    if (!o.camera.empty() || o.look_at)
        throw UsageError(
            "--soak renders every scene from its own camera: drop --camera and "
            "--look-at");
}

// Every built-in scene, then --scene when it names a file (or a built-in: already there).
std::vector<scene::Scene> soak_scenes(const Options& o, const Settings& base) {
    std::vector<scene::Scene> scenes;
    for (const auto& info : scene::builtin::list())
        scenes.push_back(load_command_scene(o, info.name, base));
    if (!scene::builtin::exists(o.scene)) scenes.push_back(load_command_scene(o, o.scene, base));
    return scenes;
}

// --size and two smaller ones (one of odd dimensions): every cycle resizes the frame often.
std::vector<Size> soak_sizes(const Size& size) {
    auto scaled = [&](uint32_t num, uint32_t den, uint32_t odd) {
        return Size{std::max(1u, size.width * num / den) | odd,
                    std::max(1u, size.height * num / den) | odd};
    };
    return {size, scaled(1, 2, 0), scaled(3, 8, 1)};
}

std::vector<SoakProbe> soak_probes(const DeviceInfo& device) {
    std::vector<SoakProbe> probes{SoakProbe::None, SoakProbe::Pixel, SoakProbe::Inspect};
    if (device.fragment_counts) probes.push_back(SoakProbe::Counts);
    if (device.draw_counts) probes.push_back(SoakProbe::Draws);
    if (device.surface_ids) probes.push_back(SoakProbe::ZFight);
    return probes;
}

struct SoakPlan {
    std::vector<scene::Scene> scenes;
    std::vector<Size> sizes;
    std::vector<int> msaa;
    std::vector<SoakProbe> probes;
    size_t frames_per_cycle = 0;
    // Warm-up: as many cycles as probes, after which every scene x msaa x prepass x probe
    // combination has been rendered once (soak_cycle's rotation).
    size_t warmup_cycles = 1;
    std::vector<SoakStep> cycle(size_t index) const {
        return soak_cycle(scenes.size(), sizes, msaa, probes, index);
    }
};

void print_plan(const SoakPlan& plan, const Options& o, const DeviceInfo& device) {
    std::string scenes, sizes, msaa, probes;
    for (const auto& s : plan.scenes) scenes += " " + s.name;
    for (const auto& s : plan.sizes)
        sizes += " " + std::to_string(s.width) + "x" + std::to_string(s.height);
    for (int n : plan.msaa) msaa += " " + std::to_string(n);
    for (SoakProbe p : plan.probes) probes += std::string(" ") + probe_name(p);
    std::printf(
        "soak: %d s on %s%s; one cycle = %zu frames, warm-up = the first %zu cycles (every "
        "combination once):\n  scenes:%s\n  sizes:%s\n  msaa:%s\n  prepass: on off\n"
        "  diagnostics:%s\n",
        o.soak_seconds, device.name.c_str(), o.validate ? ", validation on" : "",
        plan.frames_per_cycle, plan.warmup_cycles, scenes.c_str(), sizes.c_str(), msaa.c_str(),
        probes.c_str());
    std::fflush(stdout);
}

// One step's frame: the base settings with the step's knobs, read back as the probe needs.
void render_step(Renderer& renderer, const scene::Scene& scene, const Settings& base,
                 const SoakStep& step) {
    Settings settings = base;
    set_knob(settings, knobs::kMsaa, std::to_string(step.msaa));
    set_knob(settings, knobs::kPrepass, step.prepass ? "on" : "off");
    for (const auto& [name, value] : probe_settings(step.probe)) settings.set(name, value);
    const uint32_t w = step.size.width, h = step.size.height;
    switch (step.probe) {
        case SoakProbe::Pixel:
            renderer.render(scene.camera, settings,
                            {.width = w,
                             .height = h,
                             .read_back = ReadBack::Yes,
                             .inspect = {},
                             .pixel = PixelQuery{w / 2, h / 2}});
            break;
        case SoakProbe::Inspect:
            renderer.render(scene.camera, settings,
                            {.width = w,
                             .height = h,
                             .read_back = ReadBack::Color,
                             .inspect = {InspectRequest{"depth"}}});
            break;
        default:
            renderer.render(scene.camera, settings,
                            {.width = w, .height = h, .read_back = ReadBack::No});
    }
}

struct SoakRun {
    uint64_t start_rss = 0;
    std::vector<RssSample> cycle_ends;
    uint64_t frames = 0;
    double seconds = 0;
};

// Whole cycles until `seconds` have passed (the last one runs to its end), and at least the
// warm-up and one cycle more to judge by.
SoakRun run_cycles(Renderer& renderer, const SoakPlan& plan, const Settings& base, int seconds) {
    SoakRun run;
    run.start_rss = resident_bytes();
    std::printf("soak: RSS %.1f MiB before the first frame\n", mib(run.start_rss));
    const Clock::time_point start = Clock::now();
    std::optional<size_t> loaded;
    while (run.cycle_ends.size() <= plan.warmup_cycles || seconds_since(start) < seconds) {
        const double cycle_start = seconds_since(start);
        for (const SoakStep& step : plan.cycle(run.cycle_ends.size())) {
            if (loaded != step.scene) renderer.set_scene(plan.scenes[step.scene]);
            loaded = step.scene;
            render_step(renderer, plan.scenes[step.scene], base, step);
            ++run.frames;
        }
        run.cycle_ends.push_back({seconds_since(start), resident_bytes(), heap_in_use_bytes()});
        const RssSample& s = run.cycle_ends.back();
        std::printf(
            "soak: cycle %zu%s: %zu frames in %.1f s (%.0f s, %llu frames in all), RSS "
            "%.1f MiB, heap in use %.1f MiB\n",
            run.cycle_ends.size(), run.cycle_ends.size() <= plan.warmup_cycles ? " (warm-up)" : "",
            plan.frames_per_cycle, s.seconds - cycle_start, s.seconds,
            static_cast<unsigned long long>(run.frames), mib(s.bytes), mib(s.heap_bytes));
        std::fflush(stdout);
    }
    run.seconds = seconds_since(start);
    return run;
}

void print_verdict(const RssVerdict& v, const RssTolerance& tol, const SoakRun& run,
                   const SoakPlan& plan) {
    std::printf("\nsoak: %.1f s, %zu cycles, %llu frames\n", run.seconds, run.cycle_ends.size(),
                static_cast<unsigned long long>(run.frames));
    std::printf("  %-10s %9.1f MiB   (renderer and scenes ready, before the first frame)\n",
                "RSS start", mib(v.start));
    std::printf("  %-10s %9.1f MiB   (after cycle %zu: every combination once)\n", "warm-up",
                mib(v.warm), plan.warmup_cycles);
    std::printf("  %-10s %9.1f MiB   (after cycle %zu)\n", "end", mib(v.end),
                run.cycle_ends.size());
    std::printf(
        "  %-10s %+9.1f MiB   (%+.2f %%; slope %+.3f MiB/min over the cycle ends; "
        "tolerance: %.0f MiB and %.0f %%)\n",
        "growth", v.growth_mib, v.growth_percent, v.slope_mib_per_min, tol.mib, tol.percent);
    std::printf(
        "  %-10s %+9.1f MiB   (RSS over the second half after warm-up; a leak grows "
        "there, more than %.0f MiB)\n",
        "late", v.late_growth_mib, tol.mib / 2.0);
    std::printf("  %-10s %+9.1f MiB   (%+.2f %%: this process's own allocations)\n", "heap",
                v.heap_growth_mib, v.heap_growth_percent);
}

nlohmann::json soak_json(const RssVerdict& v, const RssTolerance& tol, const SoakRun& run,
                         const SoakPlan& plan) {
    nlohmann::json cycles = nlohmann::json::array();
    for (const RssSample& s : run.cycle_ends)
        cycles.push_back({{"seconds", s.seconds},
                          {"rss_mib", mib(s.bytes)},
                          {"heap_in_use_mib", mib(s.heap_bytes)}});
    nlohmann::json scenes = nlohmann::json::array();
    for (const auto& s : plan.scenes) scenes.push_back(s.name);
    return {{"seconds", run.seconds},
            {"frames", run.frames},
            {"frames_per_cycle", plan.frames_per_cycle},
            {"warmup_cycles", plan.warmup_cycles},
            {"scenes", scenes},
            {"rss_mib", {{"start", mib(v.start)}, {"warm", mib(v.warm)}, {"end", mib(v.end)}}},
            {"growth_mib", v.growth_mib},
            {"growth_percent", v.growth_percent},
            {"slope_mib_per_min", v.slope_mib_per_min},
            {"late_growth_mib", v.late_growth_mib},
            {"heap_growth_mib", v.heap_growth_mib},
            {"heap_growth_percent", v.heap_growth_percent},
            {"rss_growing", v.rss_growing},
            {"heap_growing", v.heap_growing},
            {"tolerance", {{"mib", tol.mib}, {"percent", tol.percent}}},
            {"cycle_ends", cycles},
            {"growing", v.growing}};
}

}  // namespace

int run_soak(const Options& o) {
    check_soak_usage(o);
    Settings base;
    for (const auto& assignment : o.sets) base.apply(assignment);
    if (!o.out.empty()) capture::check_output_file("--json", o.out);  // before any frame
    SoakPlan plan;
    plan.scenes = soak_scenes(o, base);
    RendererOptions renderer_options;
    renderer_options.validate = o.validate;
    renderer_options.device = o.device;
    Renderer renderer(renderer_options);
    const DeviceInfo device = device_info(renderer);
    plan.sizes = soak_sizes(o.size);
    plan.msaa = device.msaa_counts;
    plan.probes = soak_probes(device);
    plan.frames_per_cycle = plan.cycle(0).size();
    plan.warmup_cycles = plan.probes.size();
    print_plan(plan, o, device);

    const SoakRun run = run_cycles(renderer, plan, base, o.soak_seconds);
    const RssTolerance tolerance;
    const RssVerdict verdict = judge_rss(
        run.start_rss, std::span(run.cycle_ends).subspan(plan.warmup_cycles - 1), tolerance);
    print_verdict(verdict, tolerance, run, plan);
    const int validation = validation_exit_code(renderer);  // after teardown's leak check
    if (!o.out.empty()) {
        nlohmann::json out = soak_json(verdict, tolerance, run, plan);
        out["validation_messages"] = renderer.validation_message_count();
        capture::write_json_atomically("--json", o.out, {{"soak", out}});
        std::printf("soak: wrote %s\n", o.out.c_str());
    }
    if (verdict.growing) {
        char text[320];
        if (verdict.heap_growing)
            std::snprintf(text, sizeof text,
                          "soak: heap in use grew %.1f MiB (%.1f %%) after warm-up: above the "
                          "tolerance (%.0f MiB and %.0f %%)",
                          verdict.heap_growth_mib, verdict.heap_growth_percent, tolerance.mib,
                          tolerance.percent);
        else
            std::snprintf(text, sizeof text,
                          "soak: resident memory grew %.1f MiB (%.1f %%) after warm-up, from "
                          "%.1f to %.1f MiB, %.1f MiB of it in the second half: above the "
                          "tolerance (%.0f MiB and %.0f %%, still growing)",
                          verdict.growth_mib, verdict.growth_percent, mib(verdict.warm),
                          mib(verdict.end), verdict.late_growth_mib, tolerance.mib,
                          tolerance.percent);
        throw Error(text);
    }
    std::printf("soak: resident memory flat after warm-up%s\n",
                validation ? "" : (o.validate ? ", no validation messages" : ""));
    return validation;
}

}  // namespace ds::app
