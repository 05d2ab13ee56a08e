// replay: render a capture again from its report.json (issue 13 part 3) and say whether
// final.png came out bit-identical.
#include <cstdio>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "app/capture_job.h"
#include "app/commands.h"
#include "renderer/capture/replay_info.h"
#include "renderer/common/error.h"
#include "renderer/common/quoted.h"
#include "renderer/common/sha256.h"
#include "renderer/common/version.h"
#include "renderer/scene/loader.h"

namespace ds::app {
namespace {

namespace fs = std::filesystem;

// A report is a few MiB at most (the graph, the draws); anything far larger is not one.
constexpr std::uintmax_t kMaxReportBytes = 256u << 20;

std::string slurp(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    if (!in && !in.eof()) throw Error(escaped(path.string()) + ": cannot read");
    return bytes.str();
}

nlohmann::json read_report(const fs::path& path) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec))
        throw Error(escaped(path.string()) + ": no such file (not a capture folder?)");
    if (fs::file_size(path, ec) > kMaxReportBytes)
        throw Error(escaped(path.string()) + ": larger than any report");
    nlohmann::json report = nlohmann::json::parse(slurp(path), nullptr, /*allow_exceptions=*/false);
    if (report.is_discarded()) throw Error(escaped(path.string()) + ": not JSON");
    return report;
}

// The scene as captured: a built-in one rebuilt with the (replayed) settings, or the file,
// which must be the one captured (the same SHA-256) unless --force.
scene::Scene load_captured_scene(const capture::ReplayInfo& info, const Settings& settings,
                                 bool force) {
    if (!info.builtin.empty()) return scene::load_scene(info.builtin, settings);
    std::error_code ec;
    if (!fs::is_regular_file(info.file, ec))
        throw Error(escaped(info.file.string()) + ": the captured scene file is gone");
    const std::string digest = sha256_file(info.file);
    if (digest != info.sha256 && !force)
        throw Error(escaped(info.file.string()) + ": changed since the capture (sha256 " +
                    digest.substr(0, 12) + "…, captured " + info.sha256.substr(0, 12) +
                    "…); --force replays it anyway");
    return scene::load_scene(info.file.string(), settings);
}

fs::path default_out(const fs::path& dir) {
    fs::path d = dir.lexically_normal();
    if (d.filename().empty()) d = d.parent_path();
    return d.string() + "-replay";
}

}  // namespace

int run_replay(const Options& o) {
    const fs::path dir = o.capture_in;
    const fs::path report_path = dir / "report.json";
    const capture::ReplayInfo info = capture::parse_replay(read_report(report_path), report_path);
    std::error_code ec;
    if (!fs::is_regular_file(dir / "final.png", ec))
        throw Error(escaped((dir / "final.png").string()) + ": no such file");
    if (info.version != version() && !o.force)
        throw Error(escaped(report_path.string()) + ": captured by depthscope " +
                    quote(info.version) + ", this is " + quote(version()) +
                    "; --force replays it anyway");
    CaptureJob job;
    for (const std::string& s : info.settings) {
        try {
            job.settings.apply(s);
        } catch (const UsageError& e) {
            throw Error(escaped(report_path.string()) + ": settings: " + e.what());
        }
    }
    for (const std::string& s : o.sets) job.settings.apply(s);  // the A/B overrides
    job.resources = capture::parse_resource_selection(o.resources);
    job.out = o.out.empty() ? default_out(dir) : fs::path(o.out);
    job.scene = load_captured_scene(info, job.settings, o.force);
    job.scene.camera = info.camera;

    Options replay = o;
    replay.size = {info.width, info.height};
    const int code = write_capture(replay, job);
    const bool same = slurp(dir / "final.png") == slurp(job.out / "final.png");
    if (same)
        std::printf("depthscope: replay: final.png is bit-identical to %s\n", dir.c_str());
    else
        std::printf("depthscope: replay: final.png differs from %s%s (depthscope diff %s %s)\n",
                    dir.c_str(), o.sets.empty() ? "" : " (--set changed the frame)", dir.c_str(),
                    job.out.c_str());
    return code;
}

}  // namespace ds::app
