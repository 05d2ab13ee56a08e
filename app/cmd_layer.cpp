// depthscope layer: run an application under VK_LAYER_DEPTHSCOPE_diagnostics; --list its
// frames, or capture one (issue 28).
#include <unistd.h>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <map>

#include "app/commands.h"
#include "app/layer_launch.h"
#include "capture/layer_capture.h"
#include "capture/layer_frames.h"
#include "capture/output_dir.h"
#include "renderer/common/error.h"
#include "renderer/common/layer_settings.h"

namespace ds::app {

namespace {

// A private folder for the layer's files, removed at the end.
class TempDir {
  public:
    TempDir() {
        std::string pattern =
            (std::filesystem::temp_directory_path() / "depthscope-layer-XXXXXX").string();
        if (!mkdtemp(pattern.data())) throw Error("cannot make a temporary folder");
        path_ = pattern;
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    const std::filesystem::path& path() const { return path_; }

  private:
    std::filesystem::path path_;
};

// The layer's settings as DEPTHSCOPE_LAYER_SETTINGS ("k=v;k=v"), refused here when the layer
// would not take them (renderer/common/layer_settings.h).
std::string settings_text(const std::vector<std::string>& sets) {
    std::map<std::string, std::string> pairs;
    std::string out;
    for (const std::string& s : sets) {
        const auto eq = s.find('=');
        if (eq == std::string::npos || eq == 0 || s.find(';') != std::string::npos)
            throw UsageError("--set expects NAME=VALUE, got '" + s + "'");
        pairs[s.substr(0, eq)] = s.substr(eq + 1);
        out += (out.empty() ? "" : ";") + s;
    }
    parse_layer_settings(pairs);
    return out;
}

int run_list(const Options& o) {
    TempDir tmp;
    const int code =
        run_with_layer(o.layer_app, {{"DEPTHSCOPE_LAYER_OUT", tmp.path().string()},
                                     {"DEPTHSCOPE_LAYER_MODE", "list"},
                                     {"DEPTHSCOPE_LAYER_SETTINGS", settings_text(o.sets)}});
    const auto frames = capture::read_layer_frames(tmp.path() / "frames.jsonl");
    if (frames.empty())
        std::printf(
            "no frames: the application created no Vulkan device, or submitted no "
            "render pass with a depth attachment and never presented\n");
    for (const std::string& line : capture::list_lines(frames)) std::printf("%s\n", line.c_str());
    return code;
}

// The application's name for the default folder: its file name, letters and digits only.
std::string app_stem(const std::string& app) {
    std::string out;
    for (char c : std::filesystem::path(app).filename().string())
        out += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    return out.empty() ? "app" : out;
}

// Why the chosen frame never came, from the frames the layer saw.
std::string missing_frame(const Options& o, const std::filesystem::path& frames_file) {
    const auto frames = capture::read_layer_frames(frames_file);
    const bool by_present = frames.empty() || frames.back().by_present;
    const uint64_t seen = frames.empty() ? 0 : frames.back().number;
    return std::string(by_present ? "frame " : "submission ") + std::to_string(o.layer_frame) +
           " never came: the application " +
           (by_present ? "presented " + std::to_string(seen) + " frames"
                       : "made " + std::to_string(seen) + " submissions with a depth pass");
}

int run_layer_capture(const Options& o) {
    const std::filesystem::path out_path =
        o.out.empty()
            ? capture::default_capture_dir(DS_CAPTURE_ROOT, "layer-" + app_stem(o.layer_app[0]))
            : std::filesystem::path(o.out);
    capture::OutputDir out(out_path);
    TempDir tmp;
    const int code =
        run_with_layer(o.layer_app, {{"DEPTHSCOPE_LAYER_OUT", tmp.path().string()},
                                     {"DEPTHSCOPE_LAYER_MODE", "capture"},
                                     {"DEPTHSCOPE_LAYER_FRAME", std::to_string(o.layer_frame)},
                                     {"DEPTHSCOPE_LAYER_SETTINGS", settings_text(o.sets)}});
    if (!std::filesystem::exists(tmp.path() / "capture.json"))
        throw Error(missing_frame(o, tmp.path() / "frames.jsonl"));
    capture::write_layer_capture(tmp.path(), out.staging_dir(), o.layer_app);
    const std::string warning = out.commit();
    if (!warning.empty()) std::fprintf(stderr, "depthscope: warning: %s\n", warning.c_str());
    std::fprintf(stderr, "depthscope: wrote %s\n", out_path.string().c_str());
    return code;
}

}  // namespace

int run_layer(const Options& o) {
    if (o.layer_list == (o.layer_frame > 0)) throw UsageError("layer: choose --list or --frame N");
    settings_text(o.sets);  // refused before anything runs
    if (o.layer_list) return run_list(o);
    return run_layer_capture(o);
}

}  // namespace ds::app
