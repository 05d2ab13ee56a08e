// depthscope's entry point: parse, dispatch, and turn every error into one line and an exit
// code (DESIGN decision 8): 0 ok, 1 runtime or input error, 2 usage error, 3 validation.
#include <csignal>
#include <cstdio>
#include <exception>

#include "app/cli.h"
#include "app/commands.h"
#include "renderer/common/error.h"
#include "renderer/common/quoted.h"

namespace {

int dispatch(const ds::app::Options& o) {
    using ds::app::Command;
    switch (o.command) {
        case Command::Info:
            return ds::app::run_info(o);
        case Command::Scenes:
            return ds::app::run_scenes();
        case Command::Cameras:
            return ds::app::run_cameras(o);
        case Command::Settings:
            return ds::app::run_settings();
        case Command::ExportScene:
            return ds::app::run_export_scene(o);
        case Command::Capture:
            return ds::app::run_capture(o);
        case Command::Bench:
            return ds::app::run_bench(o);
        case Command::Pixel:
            return ds::app::run_pixel(o);
        case Command::Replay:
            return ds::app::run_replay(o);
        case Command::View:
            return ds::app::run_view(o);
        case Command::Diff:
            return ds::app::run_diff(o);
        case Command::Diagnose:
            return ds::app::run_diagnose(o);
        case Command::Layer:
            return ds::app::run_layer(o);
        case Command::TuneMsaa:
        case Command::TuneAlpha:
            return ds::app::run_tune(o);
        case Command::Lint:
            return ds::app::run_lint(o);
        case Command::Sweep:
            return ds::app::run_sweep(o);
        case Command::Default:
            // The inspector where there is a display; a headless capture where there is none.
            // --capture opens the inspector: without a display it fails there, not as a capture.
            if (ds::app::display_available() || !o.capture_in.empty()) return ds::app::run_view(o);
            std::fprintf(stderr, "depthscope: no display: rendering a headless capture of '%s'\n",
                         o.scene.c_str());
            return ds::app::run_capture(o);
    }
    return 2;
}

// Every echo site quotes the user's text; escaping the whole line again changes nothing there
// and keeps a message from a library (a file name, a parser's text) on one line too.
int fail(const char* what, int code) {
    std::fprintf(stderr, "depthscope: error: %s\n", ds::escaped(what).c_str());
    return code;
}

}  // namespace

int main(int argc, char** argv) {
    // Over a file-size limit (ulimit -f) a write would raise SIGXFSZ, which ends the process
    // with no word; ignored, the write fails with EFBIG and the command reports it and cleans up.
    std::signal(SIGXFSZ, SIG_IGN);
    try {
        ds::app::Options options;
        if (auto exit_code = ds::app::parse_command_line(argc, argv, options)) return *exit_code;
        return dispatch(options);
    } catch (const ds::UsageError& e) {
        return fail(e.what(), 2);
    } catch (const std::exception& e) {
        return fail(e.what(), 1);
    }
}
