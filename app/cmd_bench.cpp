// bench: render N frames per settings combination in one process; print per-pass medians.
#include <chrono>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "app/bench.h"
#include "app/commands.h"
#include "app/exit_code.h"
#include "app/scene_load.h"
#include "app/view_camera.h"
#include "capture/advice.h"
#include "capture/file_output.h"
#include "capture/report.h"
#include "capture/trace.h"
#include "renderer/common/error.h"
#include "renderer/device_info.h"
#include "renderer/renderer.h"
#include "renderer/scene/loader.h"
#include "renderer/settings/frame_knobs.h"
#include "ui/headless.h"

namespace ds::app {
namespace {

struct RunResult {
    std::vector<Assignment> assignments;
    Summary frame;         // GPU: the frame's graph (+ the UI's with --ui)
    Summary wall;          // host: the whole frame, submit to result (+ ImGui, decode, composite)
    Summary beyond_scene;  // wall minus the scene graph's GPU ms: what is not the scene
    std::vector<PassResult> passes;  // execution order, each as first seen
    std::vector<Summary> pass_ms;    // GPU, one per pass
    std::vector<std::string> skipped;
    bool ui = false;  // the inspector drawn over each frame (bench --ui)
    std::vector<std::vector<PassResult>> traced;  // --trace: each measured frame's passes
};

// One measured frame: the renderer's result and, with --ui, the UI composite's GPU ms.
struct Measured {
    const FrameResult* frame = nullptr;
    std::optional<double> ui_gpu_ms;
};

using FrameSource = std::function<Measured()>;

// The UI composite, timed as one more pass of a bench --ui run.
PassResult ui_pass() {
    PassResult pass;
    pass.name = "ui";
    return pass;
}

// The base settings with one combination of the matrix over them.
Settings combined(const Settings& base, const std::vector<Assignment>& combination) {
    Settings settings = base;
    for (const auto& [name, value] : combination) settings.set(name, value);
    return settings;
}

// Frames from each source in turn (warm-up, then measured): with --ui the plain frame and the
// inspector's alternate, so both see the same machine and the ratio holds within one run.
std::vector<RunResult> measure(const std::vector<FrameSource>& sources, const Options& o) {
    struct Samples {
        std::vector<double> frame_ms, wall_ms, beyond_ms;
        std::vector<PassResult> order;
        std::map<std::string, std::vector<double>> pass_ms;
        std::vector<std::string> skipped;
        std::vector<std::vector<PassResult>> traced;
        void add(const PassResult& pass, double ms) {
            if (!pass_ms.count(pass.name)) order.push_back(pass);
            pass_ms[pass.name].push_back(ms);
        }
    };
    for (int i = 0; i < o.bench_warmup; ++i)
        for (const FrameSource& source : sources) source();
    std::vector<Samples> samples(sources.size());
    for (int i = 0; i < o.bench_frames; ++i) {
        for (size_t k = 0; k < sources.size(); ++k) {
            Samples& s = samples[k];
            const auto start = std::chrono::steady_clock::now();
            const Measured m = sources[k]();
            s.wall_ms.push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count());
            s.frame_ms.push_back(m.frame->gpu_ms + m.ui_gpu_ms.value_or(0.0));
            s.beyond_ms.push_back(s.wall_ms.back() - m.frame->gpu_ms);
            s.skipped = m.frame->skipped;
            for (const PassResult& p : m.frame->passes) s.add(p, p.gpu_ms);
            if (!o.trace.empty()) {
                s.traced.emplace_back();
                for (const PassResult& p : m.frame->passes)
                    s.traced.back().push_back(capture::trace_pass(p));
            }
            if (m.ui_gpu_ms) s.add(ui_pass(), *m.ui_gpu_ms);
        }
    }
    std::vector<RunResult> runs;
    for (size_t k = 0; k < sources.size(); ++k) {
        RunResult run;
        run.skipped = samples[k].skipped;
        run.frame = summarize(samples[k].frame_ms);
        run.wall = summarize(samples[k].wall_ms);
        run.beyond_scene = summarize(samples[k].beyond_ms);
        run.passes = samples[k].order;
        for (const PassResult& p : run.passes)
            run.pass_ms.push_back(summarize(samples[k].pass_ms[p.name]));
        run.ui = k > 0;
        run.traced = std::move(samples[k].traced);
        runs.push_back(std::move(run));
    }
    return runs;
}

// "run 2: prepass=off + inspector"
std::string run_label(const RunResult& run, size_t index) {
    std::string label;
    for (const auto& [name, value] : run.assignments) label += " " + name + "=" + value;
    if (label.empty()) label = " (defaults)";
    if (run.ui) label += " + inspector";
    return "run " + std::to_string(index + 1) + ":" + label;
}

void print_run(const RunResult& run, size_t index) {
    std::printf("\n%s\n", run_label(run, index).c_str());
    std::printf("  %-18s %9s %9s %9s   (GPU ms)\n", "pass", "median", "min", "max");
    for (size_t i = 0; i < run.passes.size(); ++i) {
        const Summary& s = run.pass_ms[i];
        std::printf("  %-18s %9.3f %9.3f %9.3f\n", run.passes[i].name.c_str(), s.median, s.min,
                    s.max);
    }
    std::printf("  %-18s %9.3f %9.3f %9.3f\n", "frame", run.frame.median, run.frame.min,
                run.frame.max);
    std::printf("  %-18s %9.3f %9.3f %9.3f   (host ms, whole frame)\n", "wall", run.wall.median,
                run.wall.min, run.wall.max);
    for (const auto& note : run.skipped) std::printf("  (%s)\n", note.c_str());
}

nlohmann::json summary_json(const Summary& s) {
    return {{"median", s.median}, {"min", s.min}, {"max", s.max}};
}

nlohmann::json runs_json(const std::vector<RunResult>& runs, const Settings& base) {
    nlohmann::json out = nlohmann::json::array();
    for (const RunResult& run : runs) {
        const Settings settings = combined(base, run.assignments);
        const nlohmann::json passes = capture::passes_json(run.passes, [&](size_t i) {
            nlohmann::json measured{{"gpu_ms", summary_json(run.pass_ms[i])}};
            // bench's own row for the inspector's composite is no pass of the frame.
            if (run.passes[i].name == ui_pass().name) measured["kind"] = "ui";
            return measured;
        });
        out.push_back({{"settings", settings.values()},
                       {"frame_ms", summary_json(run.frame)},
                       {"wall_ms", summary_json(run.wall)},
                       {"ui", run.ui},
                       {"passes", passes},
                       {"skipped", run.skipped}});
    }
    return out;
}

void print_header(const Options& o, const scene::Scene& scene, const Renderer& renderer) {
    std::printf("bench: %s at %ux%u, %d frames after %d warm-up, on %s%s\n", scene.name.c_str(),
                o.size.width, o.size.height, o.bench_frames, o.bench_warmup,
                device_info(renderer).name.c_str(),
                o.ui ? ", inspector drawn offscreen every frame"
                     : ", combinations interleaved frame by frame");
}

void print_ui_cost(const RunResult& plain, const RunResult& with_ui) {
    // Frame times swing more than the UI costs on a CPU device: the UI's cost is what a
    // frame spends beyond its scene graph's GPU time, against the same for plain frames.
    const double cost = with_ui.beyond_scene.median - plain.beyond_scene.median;
    std::printf(
        "\ninspector: wall median %.1f -> %.1f ms; beyond the scene's GPU time "
        "%.1f -> %.1f ms: the UI costs %.1f ms, %.1f %% of the frame\n",
        plain.wall.median, with_ui.wall.median, plain.beyond_scene.median,
        with_ui.beyond_scene.median, cost, 100.0 * cost / with_ui.wall.median);
}

// One combination's runs (plain, then with the inspector under --ui), printed as they end.
void bench_combination(const Options& o, Renderer& renderer, const scene::Scene& scene,
                       ui::HeadlessUi* ui, const Settings& base,
                       const std::vector<Assignment>& combination, std::vector<RunResult>& runs) {
    const Settings settings = combined(base, combination);
    FrameResult last;
    std::vector<FrameSource> sources{[&] {
        last = renderer.render(
            scene.camera, settings,
            {.width = o.size.width, .height = o.size.height, .read_back = ReadBack::No});
        return Measured{&last, std::nullopt};
    }};
    if (ui) {
        for (const auto& [name, value] : combination)
            ui->inspector().apply(ui::SetSetting{name, value});
        sources.push_back([&] {
            ui->frame();
            return Measured{&ui->inspector().frame(), ui->last_stats().gpu_ms};
        });
    }
    for (RunResult& run : measure(sources, o)) {
        run.assignments = combination;
        runs.push_back(std::move(run));
        print_run(runs.back(), runs.size() - 1);
    }
    if (ui) print_ui_cost(runs[runs.size() - 2], runs.back());
}

// Without --ui, every combination's frames interleave (frame i of each in turn, warm-up too).
// On a shared CPU device the load drifts within a run: measured one after the other, the
// combinations compared the neighbours' load as much as the settings (atrium 1280x720 on
// lavapipe beside two other builds: the same shadow pass read 46 to 85 ms across the four
// runs of one matrix, and off / on ratios swung from 1.3 to 2.4). Interleaved, the medians
// being compared come from frames that saw the same machine, as --advise and --ui already do.
void bench_interleaved(const Options& o, Renderer& renderer, const scene::Scene& scene,
                       const Settings& base,
                       const std::vector<std::vector<Assignment>>& combinations,
                       std::vector<RunResult>& runs) {
    std::vector<Settings> settings;
    for (const auto& combination : combinations) settings.push_back(combined(base, combination));
    std::vector<FrameResult> last(combinations.size());
    std::vector<FrameSource> sources;
    for (size_t k = 0; k < combinations.size(); ++k)
        sources.push_back([&, k] {
            last[k] = renderer.render(
                scene.camera, settings[k],
                {.width = o.size.width, .height = o.size.height, .read_back = ReadBack::No});
            return Measured{&last[k], std::nullopt};
        });
    std::vector<RunResult> measured = measure(sources, o);
    for (size_t k = 0; k < measured.size(); ++k) {
        measured[k].assignments = combinations[k];
        measured[k].ui = false;  // measure() takes a second source for the inspector's
        runs.push_back(std::move(measured[k]));
        print_run(runs.back(), runs.size() - 1);
    }
}

void write_results(const Options& o, const scene::Scene& scene, const nlohmann::json& runs) {
    capture::write_json_atomically("--json", o.out,
                                   {{"scene", scene.name},
                                    {"size", {o.size.width, o.size.height}},
                                    {"frames", o.bench_frames},
                                    {"warmup", o.bench_warmup},
                                    {"runs", runs}});
    std::printf("\nbench: wrote %s\n", o.out.c_str());
}

// --trace: every run a process, every measured frame a track (capture/trace.h). The
// inspector's composite (bench's "ui" row) is a graph of its own and not in the trace.
void write_trace(const Options& o, const scene::Scene& scene, const Renderer& renderer,
                 const Settings& base, std::vector<RunResult>& runs) {
    capture::TraceInput trace{.command = "bench",
                              .scene = scene.name,
                              .width = o.size.width,
                              .height = o.size.height,
                              .device = device_info(renderer).name,
                              .track_per_frame = true,
                              .runs = {}};
    for (size_t i = 0; i < runs.size(); ++i)
        trace.runs.push_back({.name = run_label(runs[i], i),
                              .settings = combined(base, runs[i].assignments).values(),
                              .frames = std::move(runs[i].traced)});
    capture::write_trace(o.trace, trace);
    std::printf("\nbench: wrote %s\n", o.trace.c_str());
}

// --advise: the advisor owns the prepass knob, so a matrix over it (or --ui) is refused.
void check_advise(const Options& o, const std::vector<std::vector<Assignment>>& combinations) {
    if (!o.advise) return;
    if (o.ui) throw UsageError("--advise and --ui: one at a time");
    for (const auto& combination : combinations)
        for (const auto& [name, value] : combination)
            if (name == knobs::kPrepass.name)
                throw UsageError(
                    "--advise renders prepass=on and off itself: drop --matrix prepass=...");
}

void print_advice(const capture::Advice& a) {
    const capture::AdviceSide& on = a.input.with_prepass;
    const capture::AdviceSide& off = a.input.without;
    std::printf("  %-26s %12s %12s\n", "", "with prepass", "without");
    std::printf("  %-26s %12llu %12llu   (exact, count_fragments=on)\n", "forward shaded",
                (unsigned long long)on.forward_shaded, (unsigned long long)off.forward_shaded);
    std::printf("  %-26s %12.3f %12.3f   (GPU ms, medians)\n", "depth_prepass + resolve",
                on.depth_ms, off.depth_ms);
    std::printf("  %-26s %12.3f %12.3f\n", "forward", on.forward_ms, off.forward_ms);
    std::printf("  %-26s %12.3f %12.3f\n", "frame", on.frame_ms, off.frame_ms);
    std::printf("  %-26s %12.3f %12.3f\n", "forward ns per fragment", a.ns_per_fragment_with,
                a.ns_per_fragment_without);
    std::printf(
        "  overdraw %.3f (%llu pixels covered); keeping the prepass: predicted %+.3f ms, "
        "measured %+.3f ms (whole frame %+.3f ms, with the passes only the prepass feeds)\n",
        a.overdraw, (unsigned long long)off.covered_pixels, a.predicted_change_ms,
        a.measured_change_ms, a.frame_change_ms);
    std::printf("verdict: %s\n", capture::verdict_line(a).c_str());
}

// One combination through the advisor: both configurations, counted once, timed alternately.
nlohmann::json advise_combination(const Options& o, Renderer& renderer, const scene::Scene& scene,
                                  const Settings& base, const std::vector<Assignment>& combination,
                                  size_t index) {
    const Settings settings = combined(base, combination);
    std::string label;
    for (const auto& [name, value] : combination) label += " " + name + "=" + value;
    std::printf("\nadvice %zu:%s\n", index + 1, label.empty() ? " (defaults)" : label.c_str());
    const capture::RenderFrame render = [&](const Settings& s) {
        return renderer.render(
            scene.camera, s,
            {.width = o.size.width, .height = o.size.height, .read_back = ReadBack::No});
    };
    const capture::Advice advice = capture::advise(capture::measure_advice(
        settings, render, {.frames = o.bench_frames, .warmup = o.bench_warmup}));
    print_advice(advice);
    return {{"settings", settings.values()}, {"advice", capture::advice_json(advice)}};
}

}  // namespace

int run_bench(const Options& o) {
    if (!o.trace.empty() && (o.soak_seconds > 0 || o.advise))
        throw UsageError("--trace and --" + std::string(o.advise ? "advise" : "soak") +
                         ": one at a time");
    if (o.soak_seconds > 0) return run_soak(o);  // cmd_soak.cpp
    Settings base;
    for (const auto& assignment : o.sets) base.apply(assignment);
    const auto combinations = expand_matrix(o.matrix);
    // Check every combination before the first frame: a typo should not cost a long run.
    for (const auto& combination : combinations) combined(base, combination);  // throws
    check_advise(o, combinations);
    // --json's target before any frame: a directory or a device node there is refused now,
    // not after the whole benchmark.
    if (!o.out.empty()) capture::check_output_file("--json", o.out);
    if (!o.trace.empty()) capture::check_output_file("--trace", o.trace);
    scene::Scene scene = load_command_scene(o, o.scene, base);
    scene.camera = view_camera(o, scene);  // --camera, --look-at
    RendererOptions renderer_options;
    renderer_options.validate = o.validate;
    renderer_options.device = o.device;
    Renderer renderer(renderer_options);
    if (!o.trace.empty()) capture::check_trace_device(o.trace, device_info(renderer));
    renderer.set_scene(scene);
    print_header(o, scene, renderer);
    // --ui: the inspector at --size over a scene frame of --size, drawn every frame.
    std::unique_ptr<ui::HeadlessUi> ui;
    if (o.ui)
        ui = std::make_unique<ui::HeadlessUi>(renderer, base, scene,
                                              VkExtent2D{o.size.width, o.size.height},
                                              VkExtent2D{o.size.width, o.size.height});

    nlohmann::json runs_out = nlohmann::json::array();
    if (o.advise) {
        for (size_t i = 0; i < combinations.size(); ++i)
            runs_out.push_back(advise_combination(o, renderer, scene, base, combinations[i], i));
    } else {
        std::vector<RunResult> runs;
        if (ui) {
            for (const auto& combination : combinations)
                bench_combination(o, renderer, scene, ui.get(), base, combination, runs);
        } else {
            bench_interleaved(o, renderer, scene, base, combinations, runs);
        }
        runs_out = runs_json(runs, base);
        if (!o.trace.empty()) write_trace(o, scene, renderer, base, runs);
    }
    if (!o.out.empty()) write_results(o, scene, runs_out);
    ui.reset();  // it draws on the renderer's device: before the renderer's shutdown
    // No count line: bench never printed one (the messages themselves came as they were seen).
    return validation_exit_code(renderer, /*print_count=*/false);
}

}  // namespace ds::app
