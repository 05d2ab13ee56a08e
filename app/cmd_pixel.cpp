// pixel: one frame headless with a pixel history; the table on stdout, the JSON with --json.
#include <cstdio>
#include <filesystem>
#include <string>

#include "app/commands.h"
#include "app/exit_code.h"
#include "app/scene_load.h"
#include "app/view_camera.h"
#include "capture/file_output.h"
#include "capture/pixel_report.h"
#include "capture/report.h"
#include "renderer/common/error.h"
#include "renderer/renderer.h"
#include "renderer/scene/loader.h"

namespace ds::app {
namespace {

// Before any Vulkan work: the pixel must lie in the frame, and --json must name a regular file
// or a new one in an existing folder.
void check_input(const Options& o) {
    if (o.at_x >= o.size.width || o.at_y >= o.size.height) {
        throw UsageError(
            "--at " + std::to_string(o.at_x) + "," + std::to_string(o.at_y) + " is outside the " +
            std::to_string(o.size.width) + "x" + std::to_string(o.size.height) + " frame (x < " +
            std::to_string(o.size.width) + ", y < " + std::to_string(o.size.height) + ")");
    }
    if (!o.out.empty()) capture::check_output_file("--json", o.out);
}

}  // namespace

int run_pixel(const Options& o) {
    Settings settings;
    for (const auto& assignment : o.sets) settings.apply(assignment);
    check_input(o);
    scene::Scene scene = load_command_scene(o, o.scene, settings);
    scene.camera = view_camera(o, scene);

    RendererOptions renderer_options;
    renderer_options.validate = o.validate;
    renderer_options.device = o.device;
    Renderer renderer(renderer_options);
    renderer.set_scene(scene);
    const FrameResult frame = renderer.render(scene.camera, settings,
                                              {.width = o.size.width,
                                               .height = o.size.height,
                                               .read_back = ReadBack::Yes,
                                               .inspect = {},
                                               .pixel = PixelQuery{o.at_x, o.at_y}});
    const capture::PixelReportInput report{scene, settings, frame};
    std::fputs(capture::pixel_history_table(report).c_str(), stdout);
    if (!o.out.empty()) {
        capture::write_json_atomically("--json", o.out, capture::pixel_history_json(report));
        std::printf("depthscope: wrote %s\n", o.out.c_str());
    }
    return validation_exit_code(renderer);
}

}  // namespace ds::app
