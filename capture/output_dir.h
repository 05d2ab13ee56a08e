#pragma once
// A capture folder that appears complete or not at all (DESIGN decision 8): files are written
// into a staging folder beside the final one, which commit() moves into place in one step: a
// rename for a new folder, an exchange (renameat2 RENAME_EXCHANGE) for an existing one, whose
// old files are removed only afterwards. Without commit(), and on SIGTERM, SIGINT, SIGHUP or
// SIGPIPE, the staging folder is removed, so a failed capture leaves nothing behind and an
// existing folder exactly as it was.
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

namespace ds::capture {

class RemoveOnSignal;

// What an existing folder may hold for an OutputDir to replace it: `accepts` says yes for
// each entry, `what` names the folder's kind in the refusal ("a capture").
struct ReplaceableContent {
    std::function<bool(const std::filesystem::directory_entry&)> accepts;
    std::string what;
};

class OutputDir {
  public:
    // Throws ds::Error ("DIR: …") when the staging folder cannot be made, when DIR exists and
    // is no folder, or when it holds anything but a capture's files (final.png, report.json,
    // resources/,
    // *.rdc): a capture replaces its folder whole, and must never take a user's other files.
    explicit OutputDir(std::filesystem::path final_dir);
    // The same for another kind of folder (a sweep's job folder): `content` says what it may
    // hold.
    OutputDir(std::filesystem::path final_dir, const ReplaceableContent& content);
    ~OutputDir();
    OutputDir(const OutputDir&) = delete;
    OutputDir& operator=(const OutputDir&) = delete;

    // Where to write `name` now (inside the staging folder).
    std::filesystem::path staging_path(const std::string& name) const;
    const std::filesystem::path& staging_dir() const { return staging_; }
    const std::filesystem::path& final_dir() const { return final_; }

    // Puts the staged folder in place. Throws ds::Error on failure, leaving an existing folder
    // untouched. Returns a warning when the capture is in place but the replaced files could
    // not all be removed (they stay in the staging folder's name); else "".
    [[nodiscard]] std::string commit();

  private:
    std::filesystem::path final_;   // as given (messages)
    std::filesystem::path target_;  // the real folder: absolute, a symbolic link resolved
    std::filesystem::path staging_;
    std::unique_ptr<RemoveOnSignal> on_signal_;
    bool final_existed_ = false;
    bool committed_ = false;
};

// captures/YYYYmmdd-HHMMSS-SCENE under `root`, with -2, -3 … appended when taken.
std::filesystem::path default_capture_dir(const std::filesystem::path& root,
                                          const std::string& scene_name);

}  // namespace ds::capture
