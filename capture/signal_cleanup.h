#pragma once
// Output that a signal must not leave behind (DESIGN decision 8): while a RemoveOnSignal lives,
// SIGTERM, SIGINT, SIGHUP and SIGPIPE first remove its path (a staging folder and the files in
// it, or a temporary file) and then end the process as the signal would have.
#include <filesystem>

namespace ds::capture {

class RemoveOnSignal {
  public:
    enum class Kind { File, Folder };

    // Remembers `path` in static storage, so that the handler needs no allocation; installs
    // the handlers the first time (only for signals whose action is still the default: a
    // signal the process was started ignoring, SIGHUP under nohup, stays ignored). Throws
    // ds::Error when the path is too long to remember or every slot is taken.
    RemoveOnSignal(const std::filesystem::path& path, Kind kind);
    ~RemoveOnSignal();  // forgets the path (does not remove it)
    RemoveOnSignal(const RemoveOnSignal&) = delete;
    RemoveOnSignal& operator=(const RemoveOnSignal&) = delete;

  private:
    int slot_ = -1;
};

}  // namespace ds::capture
