// bench: render N frames per settings combination in one process; print per-pass medians.
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "app/bench.h"
#include "app/commands.h"
#include "renderer/capture/report.h"
#include "renderer/renderer.h"
#include "renderer/scene/loader.h"
#include "ui/headless.h"

namespace ds::app {
namespace {

struct RunResult {
    std::vector<Assignment> assignments;
    Summary frame;  // GPU: the frame's graph (+ the UI's with --ui)
    Summary wall;   // host: the whole frame, submit to result (+ ImGui, decode, composite)
    std::vector<std::pair<std::string, Summary>> passes;  // execution order
    std::vector<std::string> skipped;
};

// One measured frame: the renderer's result and, with --ui, the UI composite's GPU ms.
struct Measured {
    const FrameResult* frame = nullptr;
    std::optional<double> ui_gpu_ms;
};

template <typename RenderFrame>
RunResult measure(RenderFrame&& render_frame, const Options& o) {
    for (int i = 0; i < o.bench_warmup; ++i) render_frame();
    std::vector<double> frame_ms, wall_ms;
    std::vector<std::string> order;
    std::map<std::string, std::vector<double>> pass_ms;
    std::vector<std::string> last_skipped;
    auto add = [&](const std::string& name, double ms) {
        if (!pass_ms.count(name)) order.push_back(name);
        pass_ms[name].push_back(ms);
    };
    for (int i = 0; i < o.bench_frames; ++i) {
        const auto start = std::chrono::steady_clock::now();
        const Measured m = render_frame();
        wall_ms.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count());
        frame_ms.push_back(m.frame->gpu_ms + m.ui_gpu_ms.value_or(0.0));
        last_skipped = m.frame->skipped;
        for (const PassResult& p : m.frame->passes) add(p.name, p.gpu_ms);
        if (m.ui_gpu_ms) add("ui", *m.ui_gpu_ms);
    }
    RunResult run;
    run.skipped = last_skipped;
    run.frame = summarize(frame_ms);
    run.wall = summarize(wall_ms);
    for (const auto& name : order) run.passes.emplace_back(name, summarize(pass_ms[name]));
    return run;
}

void print_run(const RunResult& run, size_t index) {
    std::string label;
    for (const auto& [name, value] : run.assignments) label += " " + name + "=" + value;
    std::printf("\nrun %zu:%s\n", index + 1, label.empty() ? " (defaults)" : label.c_str());
    std::printf("  %-18s %9s %9s %9s   (GPU ms)\n", "pass", "median", "min", "max");
    for (const auto& [name, s] : run.passes) {
        std::printf("  %-18s %9.3f %9.3f %9.3f\n", name.c_str(), s.median, s.min, s.max);
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
        Settings settings = base;
        for (const auto& [name, value] : run.assignments) settings.set(name, value);
        nlohmann::json passes = nlohmann::json::array();
        for (const auto& [name, s] : run.passes) {
            passes.push_back({{"name", name}, {"gpu_ms", summary_json(s)}});
        }
        out.push_back({{"settings", settings.values()},
                       {"frame_ms", summary_json(run.frame)},
                       {"wall_ms", summary_json(run.wall)},
                       {"passes", passes},
                       {"skipped", run.skipped}});
    }
    return out;
}

}  // namespace

int run_bench(const Options& o) {
    Settings base;
    for (const auto& assignment : o.sets) base.apply(assignment);
    const auto combinations = expand_matrix(o.matrix);
    // Check every combination before the first frame: a typo should not cost a long run.
    for (const auto& combination : combinations) {
        Settings s = base;
        for (const auto& [name, value] : combination) s.set(name, value);
    }
    const scene::Scene scene = scene::load_scene(o.scene, base);
    RendererOptions renderer_options;
    renderer_options.validate = o.validate;
    renderer_options.device = o.device;
    Renderer renderer(renderer_options);
    renderer.set_scene(scene);
    std::printf("bench: %s at %ux%u, %d frames after %d warm-up, on %s%s\n", scene.name.c_str(),
                o.size.width, o.size.height, o.bench_frames, o.bench_warmup,
                renderer.device_report().candidate.name.c_str(),
                o.ui ? ", inspector drawn offscreen every frame" : "");
    // --ui: the inspector at --size over a scene frame of --size, drawn every frame.
    std::unique_ptr<ui::HeadlessUi> ui;
    if (o.ui)
        ui = std::make_unique<ui::HeadlessUi>(renderer, base, scene,
                                              VkExtent2D{o.size.width, o.size.height},
                                              VkExtent2D{o.size.width, o.size.height});

    std::vector<RunResult> runs;
    for (const auto& combination : combinations) {
        Settings settings = base;
        for (const auto& [name, value] : combination) settings.set(name, value);
        FrameResult last;
        if (ui) {
            for (const auto& [name, value] : combination)
                ui->inspector().apply(ui::SetSetting{name, value});
            runs.push_back(measure(
                [&] {
                    ui->frame();
                    return Measured{&ui->inspector().frame(), ui->last_stats().gpu_ms};
                },
                o));
        } else {
            runs.push_back(measure(
                [&] {
                    last = renderer.render(scene.camera, settings, o.size.width, o.size.height,
                                           ReadBack::No);
                    return Measured{&last, std::nullopt};
                },
                o));
        }
        runs.back().assignments = combination;
        print_run(runs.back(), runs.size() - 1);
    }
    if (!o.out.empty()) {
        capture::write_json_atomically(o.out, {{"scene", scene.name},
                                               {"size", {o.size.width, o.size.height}},
                                               {"frames", o.bench_frames},
                                               {"warmup", o.bench_warmup},
                                               {"runs", runs_json(runs, base)}});
        std::printf("\nbench: wrote %s\n", o.out.c_str());
    }
    return renderer.validation_message_count() ? 3 : 0;
}

}  // namespace ds::app
