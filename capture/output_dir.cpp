#include "capture/output_dir.h"

#include <fcntl.h>
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <system_error>

#include "capture/signal_cleanup.h"
#include "renderer/common/error.h"
#include "renderer/common/quoted.h"

namespace fs = std::filesystem;

namespace ds::capture {
namespace {

[[noreturn]] void fail(const fs::path& path, const std::string& what, int error) {
    throw Error(escaped(path.string()) + ": " + what + ": " + std::strerror(error));
}

// A capture's resources/ folder: a real folder of *.png and *.exr files only.
bool is_resources_dir(const fs::directory_entry& entry) {
    std::error_code ec;
    if (entry.path().filename() != "resources" || !entry.is_directory(ec) || entry.is_symlink(ec))
        return false;
    for (fs::directory_iterator it(entry.path(), ec), end; !ec && it != end; it.increment(ec)) {
        const fs::path ext = it->path().extension();
        if (!it->is_regular_file(ec) || it->is_symlink(ec) || (ext != ".png" && ext != ".exr"))
            return false;
    }
    return !ec;
}

// What a capture writes; an existing folder holding only these may be replaced.
bool is_capture_file(const fs::directory_entry& entry) {
    std::error_code ec;
    if (is_resources_dir(entry)) return true;
    if (!entry.is_regular_file(ec) || entry.is_symlink(ec)) return false;
    const std::string name = entry.path().filename().string();
    return name == "final.png" || name == "report.json" || entry.path().extension() == ".rdc";
}

// Throws when `dir` holds anything a capture did not write (a folder named report.json too).
void check_replaceable(const fs::path& shown, const fs::path& dir,
                       const ReplaceableContent& content) {
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        if (!content.accepts(*it))
            throw Error(escaped(shown.string()) + ": exists and holds more than " + content.what +
                        " (" + quote(it->path().filename().string()) + "); " + content.what +
                        " replaces its folder whole: choose another --out");
    }
    if (ec) fail(shown, "cannot read folder", ec.value());
}

// The folder the capture goes to: absolute, without "." or a trailing '/', a symbolic link
// to a folder resolved (the link stays; its folder is replaced).
fs::path real_target(const fs::path& given) {
    std::error_code ec;
    fs::path target = fs::weakly_canonical(fs::absolute(given), ec);
    if (ec) fail(given, "cannot resolve", ec.value());
    if (!target.has_filename()) target = target.parent_path();
    return target;
}

}  // namespace

OutputDir::OutputDir(fs::path final_dir)
    : OutputDir(std::move(final_dir), ReplaceableContent{is_capture_file, "a capture"}) {}

OutputDir::OutputDir(fs::path final_dir, const ReplaceableContent& content)
    : final_(std::move(final_dir)), target_(real_target(final_)) {
    struct stat st {};
    final_existed_ = ::stat(target_.c_str(), &st) == 0;
    if (final_existed_ && !S_ISDIR(st.st_mode))
        throw Error(escaped(final_.string()) + ": exists and is not a folder");
    if (final_existed_) check_replaceable(final_, target_, content);
    std::error_code ec;
    fs::create_directories(target_.parent_path(), ec);
    if (ec) fail(target_.parent_path(), "cannot create folder", ec.value());
    // Beside the final folder, on its file system: commit() is one rename.
    staging_ = target_.string() + ".tmp-" + std::to_string(::getpid());
    on_signal_ = std::make_unique<RemoveOnSignal>(staging_, RemoveOnSignal::Kind::Folder);
    fs::remove_all(staging_, ec);              // a leftover of an earlier process with this id
    if (::mkdir(staging_.c_str(), 0777) != 0)  // named as given: the staging name is ours
        fail(final_, "cannot create folder", errno);
}

OutputDir::~OutputDir() {
    if (committed_) return;
    std::error_code ec;
    fs::remove_all(staging_, ec);  // leave nothing half-written behind
}

fs::path OutputDir::staging_path(const std::string& name) const {
    return staging_ / name;
}

std::string OutputDir::commit() {
    if (!final_existed_) {
        // NOREPLACE: a folder made meanwhile is not taken over (rename would take an empty one).
        int result =
            ::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, target_.c_str(), RENAME_NOREPLACE);
        if (result != 0 && errno == EINVAL)  // a file system without renameat2's flags
            result = ::rename(staging_.c_str(), target_.c_str());
        if (result != 0) fail(final_, "cannot move capture into place", errno);
        committed_ = true;
        on_signal_.reset();
        return {};
    }
    // One step: the new folder takes the old one's place, and staging_ then holds the old
    // files. A file system that cannot exchange is refused rather than replaced file by file.
    if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) != 0)
        fail(final_, "cannot replace the existing folder (renameat2 RENAME_EXCHANGE)", errno);
    committed_ = true;
    std::error_code ec;
    fs::remove_all(staging_, ec);  // the old files; a signal meanwhile removes them too
    on_signal_.reset();
    if (ec)
        return escaped(final_.string()) + ": replaced; the old files stay in " +
               escaped(staging_.string()) + ": " + ec.message();
    return {};
}

fs::path default_capture_dir(const fs::path& root, const std::string& scene_name) {
    const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    std::tm local{};
    localtime_r(&now, &local);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
    const std::string base = std::string(stamp) + "-" + scene_name;
    fs::path dir = root / base;
    for (int n = 2; fs::exists(dir); ++n) dir = root / (base + "-" + std::to_string(n));
    return dir;
}

}  // namespace ds::capture
