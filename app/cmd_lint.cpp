// lint: each scene's findings (capture/lint/): the summary on stdout, the reports as JSON with
// --json (written whole or not at all; an array for several scenes), the overdraw heat maps
// with --images, the exit code by --fail-on (default error). Every input is checked before
// the first frame: the --json target, the config, every scene and the view.
#include <cstdio>
#include <filesystem>

#include "app/commands.h"
#include "app/exit_code.h"
#include "app/scene_load.h"
#include "app/view_camera.h"
#include "capture/file_output.h"
#include "capture/lint/lint_config.h"
#include "capture/lint/lint_json.h"
#include "capture/lint/lint_views.h"
#include "renderer/common/error.h"
#include "renderer/renderer.h"

namespace ds::app {
namespace {

diagnose::Severity fail_level(const std::string& fail_on) {
    if (fail_on == "warning") return diagnose::Severity::Warning;
    if (fail_on == "info") return diagnose::Severity::Info;
    return diagnose::Severity::Error;
}

std::optional<lint::View> chosen_view(const Options& o, const scene::Scene& scene) {
    const std::optional<scene::Camera> camera = chosen_camera(o, scene);
    if (!camera) return std::nullopt;
    return lint::View{o.look_at ? "--look-at" : "--camera " + o.camera, "", *camera};
}

void prepare_images(const std::filesystem::path& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir))
        throw Error(dir.string() + ": cannot make the --images folder (" + ec.message() + ")");
}

}  // namespace

int run_lint(const Options& o) {
    Settings settings;
    for (const auto& assignment : o.sets) settings.apply(assignment);
    if (!o.out.empty()) capture::check_output_file("--json", o.out);
    const lint::Config config =
        o.lint_config.empty() ? lint::Config{} : lint::read_config(o.lint_config);
    std::vector<scene::Scene> scenes;
    std::vector<std::vector<lint::View>> views;
    for (const std::string& name : o.lint_scenes) {
        scenes.push_back(load_command_scene(o, name, settings));
        views.push_back(lint::scene_views(scenes.back(), chosen_view(o, scenes.back())));
    }
    if (!o.lint_images.empty()) prepare_images(o.lint_images);

    RendererOptions renderer_options;
    renderer_options.validate = o.validate;
    renderer_options.device = o.device;
    Renderer renderer(renderer_options);
    std::vector<lint::Report> reports;
    nlohmann::json json = nlohmann::json::array();
    for (size_t i = 0; i < scenes.size(); ++i) {
        renderer.set_scene(scenes[i]);
        const lint::Input in{.scene = scenes[i],
                             .settings = settings,
                             .views = views[i],
                             .thresholds = config.thresholds,
                             .width = o.size.width,
                             .height = o.size.height,
                             .renderer = &renderer,
                             .images = o.lint_images};
        reports.push_back(lint::lint_scene(in));
        lint::apply_config(config, reports.back());
        json.push_back(lint::report_json(reports.back(), scenes[i]));
    }
    std::fputs(lint::reports_text(reports).c_str(), stdout);
    if (!o.out.empty()) {
        capture::write_json_atomically("--json", o.out, json.size() == 1 ? json[0] : json);
        std::printf("depthscope: wrote %s\n", o.out.c_str());
    }
    if (const int validation = validation_exit_code(renderer)) return validation;
    const diagnose::Severity level = fail_level(o.fail_on);
    for (const lint::Report& r : reports)
        for (const diagnose::Finding& f : r.findings)
            if (int(f.severity) <= int(level)) return 1;
    return 0;
}

}  // namespace ds::app
