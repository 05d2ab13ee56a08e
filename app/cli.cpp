#include "app/cli.h"

#include <CLI/CLI.hpp>

#include "renderer/common/error.h"

namespace ds::app {
namespace {

// The subcommands whose results are read after parsing.
struct Subcommands {
    CLI::App* view = nullptr;
    CLI::App* info = nullptr;
    CLI::App* capture = nullptr;
    CLI::App* export_cmd = nullptr;
    CLI::App* bench = nullptr;
    CLI::App* pixel = nullptr;
};

// --size texts, parsed once the command is known: the window's (view) or the render's.
struct SizeTexts {
    std::string render;
    std::string window;
    std::string at;  // pixel --at
};

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

// The inspector: `depthscope [view] [--scene NAME|PATH] [--set k=v]... [--frames N]`.
void add_view_options(CLI::App& cmd, Options& o, std::string& window_text) {
    add_render_options(cmd, o, /*with_scene=*/true);
    cmd.add_option("--frames", o.view_frames, "close the window after N frames (0: never)")
        ->check(CLI::Range(0, 100000000));
    cmd.add_option("--size", window_text, "window size WIDTHxHEIGHT (default 1600x900)");
}

CLI::App* add_capture_command(CLI::App& app, Options& o, std::string& size_text) {
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
    capture->add_flag("--advise", o.advise,
                      "also render the frame without (or with) the prepass and write the "
                      "prepass advisor's `advice` into report.json");
    return capture;
}

CLI::App* add_export_scene_command(CLI::App& app, Options& o) {
    auto* export_cmd = app.add_subcommand(
        "export-scene", "write a built-in scene as OUT.gltf + OUT.bin + PNG textures");
    export_cmd->add_option("name", o.scene, "built-in scene name")->required();
    export_cmd->add_option("out", o.out, "output .gltf path")->required();
    export_cmd->add_option("--set", o.sets, "scene setting as name=value, repeatable");
    return export_cmd;
}

CLI::App* add_bench_command(CLI::App& app, Options& o, std::string& size_text) {
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
    bench->add_flag("--advise", o.advise,
                    "the prepass advisor: each combination with prepass=on and off (counted "
                    "once, timed --frames times); overdraw, costs, predicted and measured "
                    "change, verdict");
    bench
        ->add_option("--soak", o.soak_seconds,
                     "soak test: render every built-in scene (and --scene's file) at --size and "
                     "two smaller sizes, every msaa count the device has, prepass on and off and "
                     "each diagnostic, in cycles, for SECONDS (at least the warm-up and one cycle "
                     "more); fails when resident memory grew after warm-up")
        ->type_name("SECONDS")
        ->check(CLI::Range(1, 7 * 24 * 3600));
    return bench;
}

CLI::App* add_pixel_command(CLI::App& app, Options& o, SizeTexts& texts) {
    auto* pixel = app.add_subcommand(
        "pixel", "render one frame headless and list every fragment that covered one pixel");
    add_render_options(*pixel, o, /*with_scene=*/true);
    pixel->add_option("--size", texts.render, "render size WIDTHxHEIGHT (default 1280x720)");
    pixel->add_option("--at", texts.at, "the pixel X,Y (0,0 = top left)")
        ->type_name("X,Y")
        ->required();
    pixel->add_option("--json", o.out, "also write the history as JSON to FILE");
    return pixel;
}

// Every subcommand in help order; the top level takes the inspector's options too.
Subcommands add_commands(CLI::App& app, Options& o, SizeTexts& sizes) {
    Subcommands c;
    add_view_options(app, o, sizes.window);
    c.view = app.add_subcommand("view", "the inspector in a window (the default command)");
    add_view_options(*c.view, o, sizes.window);

    c.info = app.add_subcommand("info", "list Vulkan devices and their capabilities");
    c.info->add_option("--device", o.device, "mark this device as selected (index or name)");
    app.add_subcommand("scenes", "list the built-in scenes, one line each");
    app.add_subcommand("settings", "list every setting: name, type, default, range, help");

    c.capture = add_capture_command(app, o, sizes.render);
    c.export_cmd = add_export_scene_command(app, o);
    c.bench = add_bench_command(app, o, sizes.render);
    c.pixel = add_pixel_command(app, o, sizes);
    return c;
}

// The inspector's options are also the top level's (`depthscope --scene x`); before a
// command they would be lost or merged by surprise, so they must follow it.
void reject_options_before_command(const CLI::App& app) {
    if (app.get_subcommands().size() != 1) return;
    for (const char* name : {"--validate", "--device", "--scene", "--set", "--frames", "--size"})
        if (app.count(name))
            throw UsageError(std::string(name) + " before the command '" +
                             app.get_subcommands().front()->get_name() +
                             "': put options after the command (see --help)");
}

// The parse's results into `o`: the command, the sizes and whether a scene was named.
void apply_parse(CLI::App& app, const Subcommands& c, const SizeTexts& sizes, Options& o) {
    if (c.view->parsed()) o.command = Command::View;
    if (c.info->parsed()) o.command = Command::Info;
    if (app.got_subcommand("scenes")) o.command = Command::Scenes;
    if (app.got_subcommand("settings")) o.command = Command::Settings;
    if (c.capture->parsed()) o.command = Command::Capture;
    if (c.export_cmd->parsed()) o.command = Command::ExportScene;
    if (c.bench->parsed()) o.command = Command::Bench;
    if (c.pixel->parsed()) o.command = Command::Pixel;
    if (!sizes.at.empty()) parse_at(sizes.at, o.at_x, o.at_y);
    if (!sizes.render.empty()) o.size = parse_size(sizes.render);
    if (!sizes.window.empty()) {
        o.window = parse_size(sizes.window);
        if (o.command == Command::Default) o.size = o.window;  // the headless fallback
    }
    for (CLI::App* cmd : {&app, c.view, c.capture, c.bench, c.pixel})
        if (cmd->count("--scene")) o.scene_given = true;
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

void parse_at(const std::string& text, uint32_t& x, uint32_t& y) {
    unsigned px = 0, py = 0;
    char comma = 0, extra = 0;
    if (std::sscanf(text.c_str(), "%u%c%u%c", &px, &comma, &py, &extra) != 3 || comma != ',' ||
        text.find('-') != std::string::npos) {
        throw UsageError("--at expects X,Y (two whole numbers, 0,0 = top left), got '" + text +
                         "'");
    }
    x = px;
    y = py;
}

std::optional<int> parse_command_line(int argc, char** argv, Options& o) {
    CLI::App app{
        "depthscope: see inside a depth-prepass Vulkan renderer.\n"
        "Without a command it opens the inspector (`view`) when there is a display, else it "
        "renders a headless capture of the default scene.\n"
        "Exit codes: 0 ok, 1 runtime or input error, 2 usage error, 3 validation messages seen."};
    app.require_subcommand(0, 1);
    SizeTexts sizes;
    const Subcommands commands = add_commands(app, o, sizes);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        throw UsageError(std::string(e.what()) + " (see --help)");
    }

    reject_options_before_command(app);
    apply_parse(app, commands, sizes, o);
    return std::nullopt;
}

}  // namespace ds::app
