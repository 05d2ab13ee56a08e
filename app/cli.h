#pragma once
// The command line: subcommands and their options, parsed with CLI11 into plain structs.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ds::app {

enum class Command {
    Default,
    View,
    Info,
    Scenes,
    Cameras,
    Settings,
    Capture,
    ExportScene,
    Bench,
    Pixel,
    Replay,
    Diff,
    Diagnose,
    Layer,
    TuneMsaa,
    TuneAlpha,
    Lint,
    Sweep
};

struct Size {
    uint32_t width = 1280;
    uint32_t height = 720;
};

// --look-at EX,EY,EZ:TX,TY,TZ[:FOV]: a camera at E looking at T (scene units), up +Y.
struct LookAt {
    float eye[3] = {0, 0, 0};
    float target[3] = {0, 0, 0};
    std::optional<float> fov;  // vertical, degrees (kMinFov..kMaxFov); none: the scene camera's
};

struct Options {
    Command command = Command::Default;
    bool validate = false;  // VK_LAYER_KHRONOS_validation; any message -> exit code 3
    bool strict = false;    // a missing or undecodable texture is an error, not a warning
    std::string device;     // "N" or a name substring; "" = first suitable
    std::string scene = "atrium";
    bool scene_given = false;  // --scene on the command line (over the inspector's saved one)
    Size size;
    std::string out;                // capture folder / export file
    std::vector<std::string> sets;  // "name=value"
    bool renderdoc = false;
    bool dump_graph = false;
    std::string trace;              // capture / bench --trace FILE.json: Chrome trace-event JSON
    std::string resources = "all";  // capture --resources: all, none or NAME,NAME,…
    std::string capture_in;  // replay: the capture folder to render again; view --capture: to open
    bool force = false;  // replay / view --capture --force: another version or a changed scene file
    // view: the window's size and how many frames before it closes (0: until closed)
    Size window{1600, 900};
    int view_frames = 0;
    bool ui = false;  // capture --ui / bench --ui: the inspector drawn offscreen
    std::string view_resource = "final";  // capture --ui: the resource the viewer shows
    // bench
    int bench_frames = 20;
    int bench_warmup = 5;
    std::vector<std::string> matrix;  // "name=v1,v2"
    bool advise = false;
    bool reference = false;  // capture --reference: the supersampled reference as a resource   //
                             // bench / capture --advise: the prepass advisor (prepass on and off)
    int soak_seconds = 0;    // bench --soak SECONDS (0: no soak)
    // pixel: --at X,Y (checked against --size when the command runs); --json goes to `out`
    uint32_t at_x = 0, at_y = 0;
    // diff A B [--threshold N] [--max-percent P] [--out DIR]: two capture folders
    std::string diff_a, diff_b;
    int diff_threshold = 8;         // of 255, 1..255
    double diff_max_percent = 0.1;  // 0..100
    // The view a command renders (app/view_camera.h): --camera NAME|INDEX (a camera node of
    // the scene, "" = not given), --look-at, or diagnose's --camera-of DIR (a capture folder's
    // camera); none: the scene's camera (replay: the captured one).
    std::string camera;
    std::optional<LookAt> look_at;
    std::string camera_of;
    std::string fail_on;  // diagnose / lint --fail-on: "", "error", "warning" (lint: "info")
    // layer [--frame N | --list] [--out DIR] [--set k=v]… -- APP [ARGS…]
    int layer_frame = 0;  // 0: not given
    bool layer_list = false;
    std::vector<std::string> layer_app;
    // tune msaa|alpha [--cost ms|fragments] [--json FILE] [--plot FILE.png]; alpha:
    // [--material NAME]… [--step S]; --frames / --warmup time --cost ms.
    std::string tune_cost = "fragments";
    int tune_frames = 5, tune_warmup = 1;
    std::string plot;
    std::vector<std::string> tune_materials;
    float tune_step = 0.05f;
    // lint SCENE… [--json FILE] [--config FILE] [--images DIR] [--fail-on LEVEL]; --size
    // defaults to 640x360 there.
    std::vector<std::string> lint_scenes;
    std::string lint_config, lint_images;
    // sweep MANIFEST --out DIR [--shard I/N | --shards N] [--baseline DIR], or
    // sweep --merge DIR… --out DIR [--baseline DIR] (docs/sweep.md); --out goes to `out`.
    std::string sweep_manifest;
    std::vector<std::string> sweep_merge;
    std::string sweep_shard;  // "I/N" as given ("" none: the environment's, if any)
    int sweep_shards = 0;     // --shards N (Kubernetes' count; 0 none)
    std::string sweep_baseline;
};

// Parses argv. Returns the exit code to use right away (help printed: 0), or nullopt to run.
// Usage errors throw ds::UsageError.
std::optional<int> parse_command_line(int argc, char** argv, Options& options);

// The largest --size side (WIDTH and HEIGHT each 1..kMaxSize).
constexpr uint32_t kMaxSize = 16384;

// Decimal digits only, read without wrapping: no sign, space, hex, octal or exponent (CLI11
// alone takes "0x10", reads "010" as 8 and skips leading spaces). nullopt when `text` is not.
std::optional<uint32_t> parse_digits(std::string_view text);
// "640x360" -> Size: digits only, each side 1..kMaxSize; throws UsageError.
Size parse_size(const std::string& text);
// "12,34" -> (12, 34) into x, y: digits only, each below kMaxSize; throws UsageError.
void parse_at(const std::string& text, uint32_t& x, uint32_t& y);
// --look-at's field of view, vertical degrees (the fov knob's range).
constexpr float kMinFov = 10.0f;
constexpr float kMaxFov = 120.0f;
// "0,1.5,8:0,1,0" or "0,1.5,8:0,1,0:60" -> a LookAt: six finite decimal numbers, eye and target
// apart, the direction between them more than 1 degree from straight up or down, and an optional
// field of view in kMinFov..kMaxFov; throws UsageError.
LookAt parse_look_at(const std::string& text);

}  // namespace ds::app
