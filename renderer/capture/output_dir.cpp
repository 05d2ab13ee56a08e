#include "renderer/capture/output_dir.h"

#include <unistd.h>

#include <chrono>
#include <ctime>
#include <system_error>

#include "renderer/common/error.h"

namespace fs = std::filesystem;

namespace ds::capture {
namespace {

[[noreturn]] void fail(const fs::path& path, const std::string& what, const std::error_code& ec) {
    throw Error(path.string() + ": " + what + ": " + ec.message());
}

}  // namespace

OutputDir::OutputDir(fs::path final_dir) : final_(std::move(final_dir)) {
    std::error_code ec;
    final_existed_ = fs::is_directory(final_, ec);
    if (!final_existed_ && fs::exists(final_, ec)) {
        throw Error(final_.string() + ": exists and is not a folder");
    }
    // Staging lives beside (or inside) the final folder so that commit() is a cheap rename on
    // the same file system.
    const std::string tag = ".tmp-" + std::to_string(::getpid());
    staging_ = final_existed_ ? final_ / tag : fs::path(final_.string() + tag);
    fs::create_directories(staging_, ec);
    if (ec) fail(final_existed_ ? final_ : final_.parent_path(), "cannot create folder", ec);
}

OutputDir::~OutputDir() {
    if (committed_) return;
    std::error_code ec;
    fs::remove_all(staging_, ec);  // leave nothing half-written behind
}

fs::path OutputDir::staging_path(const std::string& name) const {
    return staging_ / name;
}

void OutputDir::commit() {
    std::error_code ec;
    if (!final_existed_) {
        fs::rename(staging_, final_, ec);
        if (ec) fail(final_, "cannot move capture into place", ec);
    } else {
        for (const auto& entry : fs::directory_iterator(staging_)) {
            fs::rename(entry.path(), final_ / entry.path().filename(), ec);
            if (ec) fail(final_ / entry.path().filename(), "cannot move into place", ec);
        }
        fs::remove_all(staging_, ec);
    }
    committed_ = true;
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
