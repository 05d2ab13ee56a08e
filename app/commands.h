#pragma once
// One function per subcommand; each returns the process exit code.
#include "app/cli.h"

namespace ds::app {

int run_info(const Options& options);
int run_scenes();
int run_cameras(const Options& options);  // the scene's camera nodes (--camera's choices)
int run_settings();
int run_capture(const Options& options);
int run_export_scene(const Options& options);
int run_bench(const Options& options);
int run_soak(const Options& options);  // bench --soak
int run_pixel(const Options& options);
int run_replay(const Options& options);
int run_view(const Options& options);
int run_layer_view(const Options& options);  // view --capture DIR of a layer capture
int run_diff(const Options& options);        // 0 same, 1 differs, 2 error (its own one line)
// 0, or with --fail-on 1 when a finding is at that level or above; 3 validation messages first
int run_diagnose(const Options& options);
// the application's exit code; depthscope's own (1, 2) for its own errors
int run_layer(const Options& options);
int run_tune(const Options& options);  // tune msaa | tune alpha
// 0, or 1 when a finding is at --fail-on's level (default error) or above; 3 validation first
int run_lint(const Options& options);
bool display_available();  // $DISPLAY or $WAYLAND_DISPLAY set
// 0 when every job passed (and nothing regressed against --baseline), 1 otherwise
int run_sweep(const Options& options);
bool display_available();  // $DISPLAY or $WAYLAND_DISPLAY set

}  // namespace ds::app
