// tune msaa | tune alpha (capture/tune/): the sweep on one view, its table on stdout, --json
// and --plot written whole or not at all (both checked before any work).
#include <cstdio>

#include "app/commands.h"
#include "app/exit_code.h"
#include "app/scene_load.h"
#include "app/view_camera.h"
#include "capture/file_output.h"
#include "capture/plot.h"
#include "capture/report.h"
#include "capture/tune/tune_report.h"
#include "renderer/common/error.h"
#include "renderer/metrics/ssim.h"
#include "renderer/renderer.h"

namespace ds::app {
namespace {

struct TuneRun {
    Settings settings;
    scene::Scene scene;
    scene::Camera camera;
};

TuneRun prepare(const Options& o) {
    if (o.size.width < metrics::kSsimWindow || o.size.height < metrics::kSsimWindow)
        throw UsageError("tune: --size must be at least 11x11 (SSIM's window), got " +
                         std::to_string(o.size.width) + "x" + std::to_string(o.size.height));
    TuneRun r;
    for (const auto& assignment : o.sets) r.settings.apply(assignment);
    if (!o.out.empty()) capture::check_output_file("--json", o.out);
    if (!o.plot.empty()) capture::check_output_file("--plot", o.plot);
    r.scene = load_command_scene(o, o.scene, r.settings);
    r.camera = view_camera(o, r.scene);
    // --material names before any Vulkan work (tune_alpha checks them again).
    if (o.command == Command::TuneAlpha) tune::masked_material_names(r.scene, o.tune_materials);
    return r;
}

void write_outputs(const Options& o, const std::string& text, const nlohmann::json& json,
                   const capture::Plot& plot) {
    std::fputs(text.c_str(), stdout);
    if (!o.out.empty()) {
        capture::write_json_atomically("--json", o.out, json);
        std::printf("depthscope: wrote %s\n", o.out.c_str());
    }
    if (!o.plot.empty()) {
        capture::write_plot_png(o.plot, plot);
        std::printf("depthscope: wrote %s\n", o.plot.c_str());
    }
}

tune::CostKind cost_kind(const Options& o) {
    return o.tune_cost == "ms" ? tune::CostKind::Ms : tune::CostKind::Fragments;
}

}  // namespace

int run_tune(const Options& o) {
    const TuneRun run = prepare(o);
    RendererOptions renderer_options;
    renderer_options.validate = o.validate;
    renderer_options.device = o.device;
    Renderer renderer(renderer_options);
    renderer.set_scene(run.scene);
    const VkExtent2D size{o.size.width, o.size.height};
    const tune::Timing timing{o.tune_frames, o.tune_warmup};
    if (o.command == Command::TuneMsaa) {
        const tune::MsaaTune t = tune::tune_msaa(renderer, run.scene, run.camera, run.settings,
                                                 size, cost_kind(o), timing);
        write_outputs(o, tune::msaa_text(t), tune::msaa_json(t), tune::msaa_plot(t));
    } else {
        const tune::AlphaSweep sweep{o.tune_materials, o.tune_step, cost_kind(o), timing};
        const tune::AlphaTune t =
            tune::tune_alpha(renderer, run.scene, run.camera, run.settings, size, sweep);
        write_outputs(o, tune::alpha_text(t), tune::alpha_json(t), tune::alpha_plot(t));
    }
    return validation_exit_code(renderer);
}

}  // namespace ds::app
