#include "app/capture_source.h"
#include "app/scene_load.h"

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "app/view_camera.h"
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

}  // namespace

scene::Camera captured_camera(const fs::path& dir) {
    const fs::path path = dir / "report.json";
    return capture::parse_replay(read_report(path), path).camera;
}

std::string slurp(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    if (!in && !in.eof()) throw Error(escaped(path.string()) + ": cannot read");
    return bytes.str();
}

CaptureSource read_capture_source(const fs::path& dir, const std::vector<std::string>& overrides,
                                  bool force) {
    CaptureSource c;
    c.dir = dir;
    c.report_path = dir / "report.json";
    c.info = capture::parse_replay(read_report(c.report_path), c.report_path);
    std::error_code ec;
    if (!fs::is_regular_file(dir / "final.png", ec))
        throw Error(escaped((dir / "final.png").string()) + ": no such file");
    if (c.info.version != version() && !force)
        throw Error(escaped(c.report_path.string()) + ": captured by depthscope " +
                    quote(c.info.version) + ", this is " + quote(version()) +
                    "; --force uses it anyway");
    for (const std::string& s : c.info.settings) {
        try {
            c.settings.apply(s);
        } catch (const UsageError& e) {
            throw Error(escaped(c.report_path.string()) + ": settings: " + e.what());
        }
    }
    for (const std::string& s : overrides) c.settings.apply(s);  // the A/B overrides
    return c;
}

scene::Scene load_captured_scene(const capture::ReplayInfo& info, const Settings& settings,
                                 const Options& o) {
    const bool force = o.force;
    scene::Scene scene;
    if (!info.builtin.empty()) {
        scene = load_command_scene(o, info.builtin, settings);
    } else {
        std::error_code ec;
        if (!fs::is_regular_file(info.file, ec))
            throw Error(escaped(info.file.string()) + ": the captured scene file is gone");
        const std::string digest = sha256_file(info.file);
        if (digest != info.sha256 && !force)
            throw Error(escaped(info.file.string()) + ": changed since the capture (sha256 " +
                        digest.substr(0, 12) + "…, captured " + info.sha256.substr(0, 12) +
                        "…); --force uses it anyway");
        scene = load_command_scene(o, info.file.string(), settings);
    }
    scene.camera = chosen_camera(o, scene).value_or(info.camera);
    return scene;
}

}  // namespace ds::app
