// `depthscope diff A B [--threshold N] [--max-percent P] [--out DIR]` (issue 13): two capture
// folders compared (capture/capture_diff.h has the rules), a one-screen summary on
// stdout and, with --out, a heat-map PNG per compared image and diff.json in a new folder.
// Exit codes as cmp(1) and diff(1) have them, so a script can tell a failed comparison from a
// failed command: 0 same (final.png within --max-percent), 1 differs, 2 trouble — a usage
// error as for every command, and here also what is exit 1 elsewhere (a folder that is no
// capture, an unreadable file, an output that cannot be written).
#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <optional>

#include "app/commands.h"
#include "capture/capture_diff.h"
#include "capture/diff_report.h"
#include "capture/image_writer.h"
#include "capture/layer_capture_data.h"
#include "capture/layer_diff.h"
#include "capture/output_dir.h"
#include "capture/report.h"
#include "renderer/common/error.h"
#include "renderer/common/quoted.h"

namespace fs = std::filesystem;

namespace ds::app {
namespace {

constexpr int kDiffTrouble = 2;

// --out names a new folder: an existing path (a file, a folder, a link) is refused before any
// work, so a diff never replaces anything.
void check_new_folder(const std::string& out) {
    struct stat st {};
    if (::lstat(out.c_str(), &st) == 0)
        throw Error("--out " + escaped(out) + ": exists; diff writes a new folder");
    if (errno != ENOENT) throw Error("--out " + escaped(out) + ": " + std::strerror(errno));
}

// Writes each compared image's heat map into the staging folder as it comes.
void write_heat_map(const capture::OutputDir& dir, const capture::ImageDiff& image) {
    const fs::path path = dir.staging_path(capture::heat_map_file(image));
    std::error_code ec;
    fs::create_directories(path.parent_path(), ec);
    if (ec)
        throw Error(escaped(path.parent_path().string()) +
                    ": cannot create folder: " + ec.message());
    capture::write_png_rgba8(path, image.width, image.height, capture::heat_map_rgba(image));
}

// Two layer captures (depthscope layer): their passes, draws and count images.
int diff_layer(const Options& o) {
    if (!capture::is_layer_capture(o.diff_a) || !capture::is_layer_capture(o.diff_b))
        throw Error("diff: " + escaped(o.diff_a) + " and " + escaped(o.diff_b) +
                    " are not both layer captures (depthscope layer) or both depthscope's own");
    const capture::LayerDiff result = capture::diff_layer_captures(o.diff_a, o.diff_b);
    std::string warning;
    if (!o.out.empty()) {
        capture::OutputDir dir(o.out);
        capture::write_json(dir.staging_path("diff.json"), result.to_json());
        warning = dir.commit();
    }
    std::fputs(capture::layer_diff_summary(result, o.diff_a, o.diff_b).c_str(), stdout);
    std::fflush(stdout);
    if (!warning.empty()) std::fprintf(stderr, "depthscope: warning: %s\n", warning.c_str());
    return result.same() ? 0 : 1;
}

int diff(const Options& o) {
    if (!o.out.empty()) check_new_folder(o.out);
    if (capture::is_layer_capture(o.diff_a) || capture::is_layer_capture(o.diff_b))
        return diff_layer(o);
    // Both captures are read and checked whole before anything is compared or written.
    const capture::CaptureFolder a = capture::load_capture(o.diff_a);
    const capture::CaptureFolder b = capture::load_capture(o.diff_b);
    const capture::DiffOptions options{o.diff_threshold, o.diff_max_percent};
    const capture::DiffNames names{o.diff_a, o.diff_b, o.out};

    std::optional<capture::OutputDir> dir;
    if (!o.out.empty()) dir.emplace(o.out);
    const capture::DiffResult result =
        capture::diff_captures(a, b, options, [&](const capture::ImageDiff& image) {
            if (dir) write_heat_map(*dir, image);
        });
    std::string warning;
    if (dir) {
        capture::write_json(dir->staging_path("diff.json"), capture::diff_json(result, names));
        warning = dir->commit();
    }
    std::fputs(capture::diff_summary(result, names).c_str(), stdout);
    std::fflush(stdout);
    if (!warning.empty()) std::fprintf(stderr, "depthscope: warning: %s\n", warning.c_str());
    return capture::diff_exit_code(result);
}

}  // namespace

int run_diff(const Options& options) {
    try {
        return diff(options);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "depthscope: error: %s\n", escaped(e.what()).c_str());
        return kDiffTrouble;
    }
}

}  // namespace ds::app
