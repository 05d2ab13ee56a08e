#include "app/cli.h"

#include <CLI/CLI.hpp>

#include "renderer/common/error.h"

namespace ds::app {
namespace {

// Options every rendering subcommand shares.
void add_render_options(CLI::App& cmd, Options& o, bool with_scene) {
    cmd.add_flag("--validate", o.validate,
                 "enable VK_LAYER_KHRONOS_validation; any validation message makes the exit "
                 "code 3");
    cmd.add_option("--device", o.device, "Vulkan device: index or name substring (see `info`)");
    if (with_scene) {
        cmd.add_option("--scene", o.scene, "built-in scene name (see `scenes`) or .gltf/.glb path");
    }
    cmd.add_option("--set", o.sets, "setting as name=value, repeatable (see `settings`)")
        ->type_name("NAME=VALUE");
}

}  // namespace

Size parse_size(const std::string& text) {
    unsigned w = 0, h = 0;
    char x = 0, extra = 0;
    if (std::sscanf(text.c_str(), "%u%c%u%c", &w, &x, &h, &extra) != 3 || x != 'x' || w < 1 ||
        h < 1 || w > 16384 || h > 16384) {
        throw UsageError("--size expects WIDTHxHEIGHT between 1x1 and 16384x16384, got '" + text +
                         "'");
    }
    return {w, h};
}

std::optional<int> parse_command_line(int argc, char** argv, Options& o) {
    CLI::App app{
        "depthscope: see inside a depth-prepass Vulkan renderer.\n"
        "Without a command it opens the inspector (`view`) when there is a display, else it "
        "renders a headless capture of the default scene.\n"
        "Exit codes: 0 ok, 1 runtime or input error, 2 usage error, 3 validation messages seen."};
    app.require_subcommand(0, 1);
    std::string size_text;

    // The inspector: `depthscope [view] [--scene NAME|PATH] [--set k=v]... [--frames N]`.
    std::string window_text;
    auto add_view_options = [&](CLI::App& cmd) {
        add_render_options(cmd, o, /*with_scene=*/true);
        cmd.add_option("--frames", o.view_frames, "close the window after N frames (0: never)")
            ->check(CLI::Range(0, 100000000));
        cmd.add_option("--size", window_text, "window size WIDTHxHEIGHT (default 1600x900)");
    };
    add_view_options(app);
    auto* view = app.add_subcommand("view", "the inspector in a window (the default command)");
    add_view_options(*view);

    auto* info = app.add_subcommand("info", "list Vulkan devices and their capabilities");
    info->add_option("--device", o.device, "mark this device as selected (index or name)");
    app.add_subcommand("scenes", "list the built-in scenes, one line each");
    app.add_subcommand("settings", "list every setting: name, type, default, range, help");

    auto* capture = app.add_subcommand(
        "capture", "render one frame headless; write DIR/final.png and DIR/report.json");
    add_render_options(*capture, o, /*with_scene=*/true);
    capture->add_option("--size", size_text, "render size WIDTHxHEIGHT (default 1280x720)");
    capture->add_option("--out", o.out, "output folder (default captures/YYYYmmdd-HHMMSS-SCENE/)");
    capture->add_flag("--renderdoc", o.renderdoc,
                      "bracket the frame with RenderDoc's StartFrameCapture/EndFrameCapture and "
                      "store the .rdc in the output folder (needs RenderDoc loaded)");

    capture->add_flag("--ui", o.ui,
                      "draw the inspector (every panel) over the frame into final.png, "
                      "offscreen; --size is the UI's size");
    capture->add_option("--view", o.view_resource,
                        "with --ui: the graph resource the viewer shows (default final)");
    capture->add_flag("--dump-graph", o.dump_graph,
                      "print the compiled render graph: passes, resources, barriers");

    auto* export_cmd = app.add_subcommand(
        "export-scene", "write a built-in scene as OUT.gltf + OUT.bin + PNG textures");
    export_cmd->add_option("name", o.scene, "built-in scene name")->required();
    export_cmd->add_option("out", o.out, "output .gltf path")->required();
    export_cmd->add_option("--set", o.sets, "scene setting as name=value, repeatable");

    auto* bench = app.add_subcommand(
        "bench", "render frames headless for each settings combination; per-pass GPU medians");
    add_render_options(*bench, o, /*with_scene=*/true);
    bench->add_option("--size", size_text, "render size WIDTHxHEIGHT (default 1280x720)");
    bench->add_option("--frames", o.bench_frames, "measured frames per combination (default 20)")
        ->check(CLI::Range(1, 100000));
    bench->add_option("--warmup", o.bench_warmup, "unmeasured frames first (default 5)")
        ->check(CLI::Range(0, 100000));
    bench
        ->add_option("--matrix", o.matrix,
                     "setting=value1,value2,...: one run per combination, repeatable")
        ->type_name("NAME=V1,V2");
    bench->add_option("--json", o.out, "also write the results as JSON to FILE");
    bench->add_flag("--ui", o.ui,
                    "draw the inspector offscreen every frame (its cost is measured)");

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        throw UsageError(std::string(e.what()) + " (see --help)");
    }

    // The inspector's options are also the top level's (`depthscope --scene x`); before a
    // command they would be lost or merged by surprise, so they must follow it.
    if (app.get_subcommands().size() == 1) {
        for (const char* name :
             {"--validate", "--device", "--scene", "--set", "--frames", "--size"})
            if (app.count(name))
                throw UsageError(std::string(name) + " before the command '" +
                                 app.get_subcommands().front()->get_name() +
                                 "': put options after the command (see --help)");
    }
    if (view->parsed()) o.command = Command::View;
    if (info->parsed()) o.command = Command::Info;
    if (app.got_subcommand("scenes")) o.command = Command::Scenes;
    if (app.got_subcommand("settings")) o.command = Command::Settings;
    if (capture->parsed()) o.command = Command::Capture;
    if (export_cmd->parsed()) o.command = Command::ExportScene;
    if (bench->parsed()) o.command = Command::Bench;
    if (!size_text.empty()) o.size = parse_size(size_text);
    if (!window_text.empty()) {
        o.window = parse_size(window_text);
        if (o.command == Command::Default) o.size = o.window;  // the headless fallback
    }
    for (CLI::App* cmd : {&app, view, capture, bench})
        if (cmd->count("--scene")) o.scene_given = true;
    return std::nullopt;
}

}  // namespace ds::app
