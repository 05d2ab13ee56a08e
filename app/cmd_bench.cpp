// bench: render N frames per settings combination in one process; print per-pass medians.
#include <cstdio>
#include <map>

#include <nlohmann/json.hpp>

#include "app/bench.h"
#include "app/commands.h"
#include "renderer/capture/report.h"
#include "renderer/renderer.h"
#include "renderer/scene/loader.h"

namespace ds::app {
namespace {

struct RunResult {
    std::vector<Assignment> assignments;
    Summary frame;
    std::vector<std::pair<std::string, Summary>> passes;  // execution order
    std::vector<std::string> skipped;
};

RunResult measure(Renderer& renderer, const scene::Scene& scene, const Settings& settings,
                  const Options& o) {
    for (int i = 0; i < o.bench_warmup; ++i) {
        renderer.render(scene.camera, settings, o.size.width, o.size.height, ReadBack::No);
    }
    std::vector<double> frame_ms;
    std::vector<std::string> order;
    std::map<std::string, std::vector<double>> pass_ms;
    std::vector<std::string> last_skipped;
    for (int i = 0; i < o.bench_frames; ++i) {
        const FrameResult f =
            renderer.render(scene.camera, settings, o.size.width, o.size.height, ReadBack::No);
        frame_ms.push_back(f.gpu_ms);
        last_skipped = f.skipped;
        for (const PassResult& p : f.passes) {
            if (!pass_ms.count(p.name)) order.push_back(p.name);
            pass_ms[p.name].push_back(p.gpu_ms);
        }
    }
    RunResult run;
    run.skipped = last_skipped;
    run.frame = summarize(frame_ms);
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
    Renderer renderer({.validate = o.validate, .device = o.device});
    renderer.set_scene(scene);
    std::printf("bench: %s at %ux%u, %d frames after %d warm-up, on %s\n", scene.name.c_str(),
                o.size.width, o.size.height, o.bench_frames, o.bench_warmup,
                renderer.device_report().candidate.name.c_str());

    std::vector<RunResult> runs;
    for (const auto& combination : combinations) {
        Settings settings = base;
        for (const auto& [name, value] : combination) settings.set(name, value);
        runs.push_back(measure(renderer, scene, settings, o));
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
