// diagnose: every detector that applies, on one view (capture/diagnose/diagnose_run.h): the ranked
// summary on stdout, the findings as JSON with --json (written whole or not at all), the exit
// code by --fail-on.
#include <cstdio>

#include "app/commands.h"
#include "app/exit_code.h"
#include "app/scene_load.h"
#include "app/view_camera.h"
#include "capture/diagnose/diagnose_run.h"
#include "capture/diagnose/finding_json.h"
#include "capture/file_output.h"
#include "capture/report.h"
#include "renderer/renderer.h"
#include "renderer/scene/loader.h"

namespace ds::app {

int run_diagnose(const Options& o) {
    Settings settings;
    for (const auto& assignment : o.sets) settings.apply(assignment);
    // Before any Vulkan work: the --json target, the scene and the view.
    if (!o.out.empty()) capture::check_output_file("--json", o.out);
    const scene::Scene scene = load_command_scene(o, o.scene, settings);
    const scene::Camera camera = view_camera(o, scene);

    RendererOptions renderer_options;
    renderer_options.validate = o.validate;
    renderer_options.device = o.device;
    Renderer renderer(renderer_options);
    renderer.set_scene(scene);
    const diagnose::Diagnosis d =
        diagnose::diagnose(renderer, scene, camera, settings, {o.size.width, o.size.height});
    std::fputs(diagnose::diagnosis_text(d).c_str(), stdout);
    if (!o.out.empty()) {
        capture::write_json_atomically("--json", o.out, diagnose::diagnosis_json(d));
        std::printf("depthscope: wrote %s\n", o.out.c_str());
    }
    if (const int validation = validation_exit_code(renderer)) return validation;
    if (o.fail_on.empty()) return 0;
    const auto level =
        o.fail_on == "error" ? diagnose::Severity::Error : diagnose::Severity::Warning;
    return d.has_at_least(level) ? 1 : 0;
}

}  // namespace ds::app
