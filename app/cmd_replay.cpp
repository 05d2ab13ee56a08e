// replay: render a capture again from its report.json (issue 13 part 3) and say whether
// final.png came out bit-identical.
#include <cstdio>

#include "app/capture_job.h"
#include "app/capture_source.h"
#include "app/commands.h"

namespace ds::app {
namespace {

namespace fs = std::filesystem;

fs::path default_out(const fs::path& dir) {
    fs::path d = dir.lexically_normal();
    if (d.filename().empty()) d = d.parent_path();
    return d.string() + "-replay";
}

// What the command line changed of the captured frame, said beside "differs".
const char* changed_by(const Options& o) {
    const bool view = o.look_at || !o.camera.empty();
    if (view && !o.sets.empty()) return " (--set and the view changed the frame)";
    if (view) return o.look_at ? " (--look-at changed the view)" : " (--camera changed the view)";
    return o.sets.empty() ? "" : " (--set changed the frame)";
}

}  // namespace

int run_replay(const Options& o) {
    const fs::path dir = o.capture_in;
    const CaptureSource source = read_capture_source(dir, o.sets, o.force);
    const capture::ReplayInfo& info = source.info;
    CaptureJob job;
    job.settings = source.settings;  // recorded, then the A/B overrides
    job.resources = capture::parse_resource_selection(o.resources);
    job.out = o.out.empty() ? default_out(dir) : fs::path(o.out);
    job.scene = load_captured_scene(info, job.settings, o);  // its camera, or --camera's

    Options replay = o;
    replay.size = {info.width, info.height};
    const int code = write_capture(replay, job);
    const bool same = slurp(dir / "final.png") == slurp(job.out / "final.png");
    if (same)
        std::printf("depthscope: replay: final.png is bit-identical to %s\n", dir.c_str());
    else
        std::printf("depthscope: replay: final.png differs from %s%s (depthscope diff %s %s)\n",
                    dir.c_str(), changed_by(o), dir.c_str(), job.out.c_str());
    return code;
}

}  // namespace ds::app
