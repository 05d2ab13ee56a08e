#include "app/cli.h"
#include "app/cli_options.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

#include <CLI/CLI.hpp>

#include "renderer/common/error.h"
#include "renderer/common/quoted.h"

namespace ds::app {
namespace {

// The subcommands whose results are read after parsing.
struct Subcommands {
    CLI::App* view = nullptr;
    CLI::App* info = nullptr;
    CLI::App* cameras = nullptr;
    CLI::App* capture = nullptr;
    CLI::App* export_cmd = nullptr;
    CLI::App* bench = nullptr;
    CLI::App* pixel = nullptr;
    CLI::App* replay = nullptr;
    CLI::App* layer = nullptr;
    CLI::App* diff = nullptr;
    CLI::App* diagnose = nullptr;
    TuneCommands tune;
    CLI::App* lint = nullptr;
    CLI::App* sweep = nullptr;
};

// The inspector: `depthscope [view] [--scene NAME|PATH] [--set k=v]... [--frames N]`.
void add_view_options(CLI::App& cmd, Options& o, std::optional<std::string>& window_text,
                      std::optional<std::string>& look_at_text) {
    add_render_options(cmd, o, /*with_scene=*/true);
    add_view_choice(cmd, o, look_at_text, "the scene's (or --capture's) camera at the start");
    add_count_option(cmd, "--frames", o.view_frames, 0, 100000000,
                     "close the window after N frames (0: never)");
    add_text_option(cmd, "--size", window_text, "window size WIDTHxHEIGHT (default 1600x900)")
        ->type_name("WxH");
    CLI::Option* capture =
        add_path_option(cmd, "--capture", o.capture_in,
                        "open a capture folder: its scene, camera, settings (then --set) and "
                        "size, pinned for the compare view")
            ->type_name("DIR");
    cmd.add_flag("--force", o.force,
                 "with --capture: a capture of another depthscope version, or of a scene file "
                 "that changed since")
        ->needs(capture);
}

CLI::App* add_capture_command(CLI::App& app, Options& o, SizeTexts& texts) {
    auto* capture = app.add_subcommand(
        "capture",
        "render one frame headless; write DIR/final.png, DIR/report.json and every graph "
        "image in DIR/resources/");
    add_render_options(*capture, o, /*with_scene=*/true);
    add_text_option(*capture, "--size", texts.render, "render size WIDTHxHEIGHT (default 1280x720)")
        ->type_name("WxH");
    add_view_choice(*capture, o, texts.look_at, "the scene's camera");
    add_path_option(*capture, "--out", o.out,
                    "output folder (default captures/YYYYmmdd-HHMMSS-SCENE/); an existing one "
                    "holding only a capture's files is replaced whole");
    capture->add_flag("--renderdoc", o.renderdoc,
                      "bracket the frame with RenderDoc's StartFrameCapture/EndFrameCapture and "
                      "store the .rdc in the output folder (needs RenderDoc loaded)");

    capture->add_flag("--ui", o.ui,
                      "draw the inspector (every panel) over the frame into final.png, "
                      "offscreen; --size is the UI's size");
    capture->add_option("--view", o.view_resource,
                        "with --ui: the graph resource the viewer shows (default final)");
    capture
        ->add_option("--resources", o.resources,
                     "graph images written to DIR/resources/ as NAME.png (as the viewer "
                     "shows them) and NAME.exr (raw values): all (default), none or "
                     "NAME,NAME,…")
        ->type_name("LIST");
    add_path_option(*capture, "--trace", o.trace,
                    "also write the frame's passes as Chrome trace-event JSON to FILE (GPU "
                    "timestamps; opens in ui.perfetto.dev and chrome://tracing)");
    capture->add_flag("--dump-graph", o.dump_graph,
                      "print the compiled render graph: passes, resources, barriers");
    capture->add_flag("--advise", o.advise,
                      "also render the frame without (or with) the prepass and write the "
                      "prepass advisor's `advice` into report.json");
    capture->add_flag("--reference", o.reference,
                      "also render the supersampled reference (4x4 samples per pixel, box "
                      "resolve in linear HDR; what `tune` scores against) into "
                      "resources/reference.png, .exr and reference_edges.png, and score "
                      "final.png against it in report.json `reference`");
    return capture;
}

CLI::App* add_cameras_command(CLI::App& app, Options& o) {
    auto* cameras = app.add_subcommand(
        "cameras",
        "list a scene's camera nodes, one line each: index, node name, type, vertical field of "
        "view, near and far planes (what --camera picks)");
    cameras->add_option("SCENE", o.scene, "built-in scene name (see `scenes`) or .gltf/.glb path")
        ->required();
    cameras->add_option("--set", o.sets, "scene setting as name=value, repeatable")
        ->type_name("NAME=VALUE");
    add_strict_flag(*cameras, o);
    return cameras;
}

CLI::App* add_export_scene_command(CLI::App& app, Options& o) {
    auto* export_cmd = app.add_subcommand(
        "export-scene", "write a built-in scene as OUT.gltf + OUT.bin + PNG textures");
    export_cmd->add_option("name", o.scene, "built-in scene name")->required();
    export_cmd->add_option("out", o.out, "output .gltf path")->required();
    export_cmd->add_option("--set", o.sets, "scene setting as name=value, repeatable");
    return export_cmd;
}

CLI::App* add_bench_command(CLI::App& app, Options& o, SizeTexts& texts) {
    auto* bench = app.add_subcommand(
        "bench", "render frames headless for each settings combination; per-pass GPU medians");
    add_render_options(*bench, o, /*with_scene=*/true);
    add_text_option(*bench, "--size", texts.render, "render size WIDTHxHEIGHT (default 1280x720)")
        ->type_name("WxH");
    add_view_choice(*bench, o, texts.look_at, "the scene's camera");
    add_count_option(*bench, "--frames", o.bench_frames, 1, 100000,
                     "measured frames per combination (default 20)");
    add_count_option(*bench, "--warmup", o.bench_warmup, 0, 100000,
                     "unmeasured frames first (default 5)");
    bench
        ->add_option("--matrix", o.matrix,
                     "setting=value1,value2,...: one run per combination, repeatable")
        ->type_name("NAME=V1,V2");
    add_path_option(*bench, "--json", o.out,
                    "also write the results as JSON to FILE (a new file or a regular one)");
    add_path_option(*bench, "--trace", o.trace,
                    "also write every measured frame's passes as Chrome trace-event JSON to "
                    "FILE: a process per run, a track per frame");
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
    add_text_option(*pixel, "--size", texts.render, "render size WIDTHxHEIGHT (default 1280x720)")
        ->type_name("WxH");
    add_view_choice(*pixel, o, texts.look_at, "the scene's camera");
    add_text_option(*pixel, "--at", texts.at, "the pixel X,Y (0,0 = top left)")
        ->type_name("X,Y")
        ->required();
    add_path_option(*pixel, "--json", o.out,
                    "also write the history as JSON to FILE (a new file or a regular one)");
    return pixel;
}

CLI::App* add_replay_command(CLI::App& app, Options& o, SizeTexts& texts) {
    auto* replay = app.add_subcommand(
        "replay",
        "render a capture again from its report.json (scene, camera, settings, size) "
        "into a new capture folder, and say whether final.png is bit-identical");
    replay->add_option("DIR", o.capture_in, "the capture folder")->required();
    add_render_options(*replay, o, /*with_scene=*/false);
    add_view_choice(*replay, o, texts.look_at, "the captured camera");
    add_path_option(*replay, "--out", o.out, "output folder (default DIR-replay)");
    replay
        ->add_option("--resources", o.resources,
                     "graph images to write, as for capture (default all)")
        ->type_name("LIST");
    replay->add_flag("--force", o.force,
                     "replay a capture of another depthscope version, or of a scene file that "
                     "changed since");
    return replay;
}

// "0.1" -> 0.1: decimal digits with one optional point, 0..100; throws UsageError.
double parse_percent(const std::string& option, const std::string& text) {
    double value = -1;
    const bool plain = !text.empty() && text.find_first_not_of("0123456789.") == std::string::npos;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (!plain || ec != std::errc() || ptr != text.data() + text.size() || value > 100)
        throw UsageError(option + " expects a percentage in 0..100, got " + quote(text));
    return value;
}

CLI::App* add_diff_command(CLI::App& app, Options& o) {
    auto* diff = app.add_subcommand(
        "diff",
        "compare two captures: % of pixels over the threshold per image, final.png's SSIM, "
        "the passes' GPU ms and counters; exit 0 when final.png's % is at most --max-percent, "
        "1 beyond, 2 on error");
    diff->add_option("a", o.diff_a, "capture folder A (the baseline)")->required();
    diff->add_option("b", o.diff_b, "capture folder B")->required();
    add_count_option(*diff, "--threshold", o.diff_threshold, 1, 255,
                     "8-bit data: a channel differs by at least N/255 (default 8)");
    diff->add_option_function<std::string>(
            "--max-percent",
            [&o](const std::string& text) {
                o.diff_max_percent = parse_percent("--max-percent", text);
            },
            "final.png may differ in at most P % of its pixels (default 0.1)")
        ->type_name("P");
    add_path_option(*diff, "--out", o.out,
                    "also write a heat-map PNG per compared image and diff.json into DIR (a new "
                    "folder)");
    return diff;
}

CLI::App* add_diagnose_command(CLI::App& app, Options& o, SizeTexts& texts) {
    auto* diagnose = app.add_subcommand(
        "diagnose",
        "run every detector that applies on one view (measurement knobs only): ranked findings "
        "(error: a visible artefact, warning: wasted work, info: advice), each with its "
        "magnitude, surfaces and fix, and the detectors skipped with the reason");
    add_render_options(*diagnose, o, /*with_scene=*/true);
    add_text_option(*diagnose, "--size", texts.render,
                    "render size WIDTHxHEIGHT (default 1280x720)")
        ->type_name("WxH");
    const ViewChoice view = add_view_choice(*diagnose, o, texts.look_at, "the scene's camera");
    add_path_option(*diagnose, "--camera-of", o.camera_of,
                    "instead of the scene's camera: the camera of a capture folder (its "
                    "report.json)")
        ->type_name("DIR")
        ->excludes(view.camera)
        ->excludes(view.look_at);
    add_path_option(*diagnose, "--json", o.out,
                    "also write the findings as JSON to FILE (a new file or a regular one)");
    diagnose
        ->add_option_function<std::string>(
            "--fail-on",
            [&o](const std::string& text) {
                if (text != "error" && text != "warning")
                    throw UsageError("--fail-on expects error or warning, got " + quote(text));
                o.fail_on = text;
            },
            "exit 1 when a finding is at this level or more severe (default: exit 0 whatever "
            "is found)")
        ->type_name("error|warning");
    return diagnose;
}

CLI::App* add_layer_command(CLI::App& app, Options& o) {
    auto* layer = app.add_subcommand(
        "layer",
        "run a Vulkan application with depthscope's layer (VK_LAYER_DEPTHSCOPE_diagnostics) for "
        "that process only: --list its frames, or capture --frame N's per-draw counts into a "
        "capture folder; exits with the application's exit code");
    add_count_option(*layer, "--frame", o.layer_frame, 1, 100000000,
                     "the frame to capture, from 1 (presents delimit frames; an application "
                     "that never presents: its submissions with a depth pass)");
    layer->add_flag("--list", o.layer_list,
                    "print the frames the application produced with their passes and draws");
    add_path_option(*layer, "--out", o.out,
                    "capture folder (default captures/YYYYmmdd-HHMMSS-APP/)");
    layer->add_option("--set", o.sets, "layer setting as name=value, repeatable")
        ->type_name("NAME=VALUE");
    layer->add_option("app", o.layer_app, "the application and its arguments, after --")
        ->required()
        ->type_name("-- APP [ARGS...]");
    return layer;
}

// Every subcommand in help order; the top level takes the inspector's options too.
Subcommands add_commands(CLI::App& app, Options& o, SizeTexts& sizes) {
    Subcommands c;
    add_view_options(app, o, sizes.window, sizes.look_at);
    c.view = app.add_subcommand("view", "the inspector in a window (the default command)");
    add_view_options(*c.view, o, sizes.window, sizes.look_at);

    c.info = app.add_subcommand("info", "list Vulkan devices and their capabilities");
    c.info->add_option("--device", o.device, "mark this device as selected (index or name)");
    app.add_subcommand("scenes", "list the built-in scenes, one line each");
    c.cameras = add_cameras_command(app, o);
    app.add_subcommand("settings", "list every setting: name, type, default, range, help");

    c.capture = add_capture_command(app, o, sizes);
    c.export_cmd = add_export_scene_command(app, o);
    c.bench = add_bench_command(app, o, sizes);
    c.pixel = add_pixel_command(app, o, sizes);
    c.replay = add_replay_command(app, o, sizes);
    c.diff = add_diff_command(app, o);
    c.diagnose = add_diagnose_command(app, o, sizes);
    c.layer = add_layer_command(app, o);
    c.tune = add_tune_command(app, o, sizes);
    c.lint = add_lint_command(app, o, sizes);
    c.sweep = add_sweep_command(app, o);
    return c;
}

// The inspector's options are also the top level's (`depthscope --scene x`); before a
// command they would be lost or merged by surprise, so they must follow it.
void reject_options_before_command(const CLI::App& app) {
    if (app.get_subcommands().size() != 1) return;
    for (const char* name : {"--validate", "--strict", "--device", "--scene", "--set", "--frames",
                             "--size", "--capture", "--force", "--camera", "--look-at"})
        if (app.count(name))
            throw UsageError(std::string(name) + " before the command '" +
                             app.get_subcommands().front()->get_name() +
                             "': put options after the command (see --help)");
}

// The parse's results into `o`: the command, the sizes and whether a scene was named.
void apply_parse(CLI::App& app, const Subcommands& c, const SizeTexts& sizes, Options& o) {
    if (c.view->parsed()) o.command = Command::View;
    if (c.info->parsed()) o.command = Command::Info;
    if (c.cameras->parsed()) o.command = Command::Cameras;
    if (app.got_subcommand("scenes")) o.command = Command::Scenes;
    if (app.got_subcommand("settings")) o.command = Command::Settings;
    if (c.capture->parsed()) o.command = Command::Capture;
    if (c.export_cmd->parsed()) o.command = Command::ExportScene;
    if (c.bench->parsed()) o.command = Command::Bench;
    if (c.pixel->parsed()) o.command = Command::Pixel;
    if (c.replay->parsed()) o.command = Command::Replay;
    if (c.diff->parsed()) o.command = Command::Diff;
    if (c.diagnose->parsed()) o.command = Command::Diagnose;
    if (c.layer->parsed()) o.command = Command::Layer;
    if (c.tune.msaa->parsed()) o.command = Command::TuneMsaa;
    if (c.tune.alpha->parsed()) o.command = Command::TuneAlpha;
    if (c.lint->parsed()) {
        o.command = Command::Lint;
        if (!sizes.render) o.size = {640, 360};
    }
    if (c.sweep->parsed()) o.command = Command::Sweep;
    if (sizes.at) parse_at(*sizes.at, o.at_x, o.at_y);
    if (sizes.look_at) o.look_at = parse_look_at(*sizes.look_at);
    if (sizes.render) o.size = parse_size(*sizes.render);
    if (sizes.window) {
        o.window = parse_size(*sizes.window);
        if (o.command == Command::Default) o.size = o.window;  // the headless fallback
    }
    for (CLI::App* cmd :
         {&app, c.view, c.capture, c.bench, c.pixel, c.diagnose, c.tune.msaa, c.tune.alpha})
        if (cmd->count("--scene")) o.scene_given = true;
    const bool inspector = o.command == Command::View || o.command == Command::Default;
    if (inspector && !o.capture_in.empty() && o.scene_given)
        throw UsageError("--scene with --capture: the capture names its scene");
}

}  // namespace

std::optional<int> parse_command_line(int argc, char** argv, Options& o) {
    CLI::App app{
        "depthscope: see inside a depth-prepass Vulkan renderer.\n"
        "Without a command it opens the inspector (`view`) when there is a display, else it "
        "renders a headless capture of the default scene.\n"
        "Exit codes: 0 ok, 1 runtime or input error, 2 usage error, 3 validation messages seen "
        "(diff: 0 same, 1 differs, 2 trouble; diagnose --fail-on LEVEL and lint: 1 when a finding "
        "is at LEVEL or above)."};
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
        // CLI11's messages repeat the arguments they object to.
        throw UsageError(escaped(e.what()) + " (see --help)");
    }

    reject_options_before_command(app);
    apply_parse(app, commands, sizes, o);
    return std::nullopt;
}

}  // namespace ds::app
