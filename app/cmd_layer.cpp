// depthscope layer: run an application under VK_LAYER_DEPTHSCOPE_diagnostics; --list its
// frames, or capture one (issue 28).
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <map>

#include "app/commands.h"
#include "app/layer_launch.h"
#include "capture/layer_frames.h"
#include "renderer/common/error.h"

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

std::string settings_text(const std::vector<std::string>& sets) {
    std::string out;
    for (const std::string& s : sets) {
        if (s.find('=') == std::string::npos || s.find(';') != std::string::npos)
            throw UsageError("--set expects NAME=VALUE, got '" + s + "'");
        out += (out.empty() ? "" : ";") + s;
    }
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

}  // namespace

int run_layer(const Options& o) {
    if (o.layer_list == (o.layer_frame > 0)) throw UsageError("layer: choose --list or --frame N");
    if (o.layer_list) return run_list(o);
    throw Error("layer --frame: not built yet");
}

}  // namespace ds::app
