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
        "Without a command it renders a headless capture of the default scene (the interactive "
        "inspector arrives with its own issue).\n"
        "Exit codes: 0 ok, 1 runtime or input error, 2 usage error, 3 validation messages seen."};
    app.require_subcommand(0, 1);
    std::string size_text;

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

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        throw UsageError(std::string(e.what()) + " (see --help)");
    }

    if (info->parsed()) o.command = Command::Info;
    if (app.got_subcommand("scenes")) o.command = Command::Scenes;
    if (app.got_subcommand("settings")) o.command = Command::Settings;
    if (capture->parsed()) o.command = Command::Capture;
    if (export_cmd->parsed()) o.command = Command::ExportScene;
    if (bench->parsed()) o.command = Command::Bench;
    if (!size_text.empty()) o.size = parse_size(size_text);
    return std::nullopt;
}

}  // namespace ds::app
