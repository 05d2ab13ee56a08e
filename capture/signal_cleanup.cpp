#include "capture/signal_cleanup.h"

#include <dirent.h>
#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <mutex>

#include "renderer/common/error.h"

namespace ds::capture {
namespace {

constexpr int kFree = 0, kClaimed = 1, kActive = 2;
constexpr int kSignals[] = {SIGTERM, SIGINT, SIGHUP, SIGPIPE};

// Written before `state` turns kActive and read by the handler only while it is: the atomic
// int (lock-free) orders the plain fields for the handler, on any thread.
struct Slot {
    std::atomic<int> state{kFree};
    bool folder = false;
    char path[4096] = {};
};
std::array<Slot, 4> g_slots;
static_assert(std::atomic<int>::is_always_lock_free);

// The files of a staging folder (it holds no folders), then the folder: open, getdents64,
// unlinkat and rmdir are plain system calls, safe in a handler. Entries removed while reading
// may shift the listing, so it is read again until a pass removes nothing.
void remove_folder(const char* path) {
    const int fd = ::open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd >= 0) {
        alignas(8) char buffer[4096];
        for (bool removed = true; removed;) {
            removed = false;
            ::lseek(fd, 0, SEEK_SET);
            ssize_t n = 0;
            while ((n = ::getdents64(fd, buffer, sizeof buffer)) > 0) {
                for (ssize_t at = 0; at < n;) {
                    const auto* entry = reinterpret_cast<const dirent64*>(buffer + at);
                    at += entry->d_reclen;
                    const char* name = entry->d_name;
                    if (std::strcmp(name, ".") == 0 || std::strcmp(name, "..") == 0) continue;
                    if (::unlinkat(fd, name, 0) == 0 || ::unlinkat(fd, name, AT_REMOVEDIR) == 0)
                        removed = true;
                }
            }
        }
        ::close(fd);
    }
    ::rmdir(path);
}

extern "C" void remove_and_reraise(int signal) {
    const int saved_errno = errno;
    for (Slot& slot : g_slots) {
        if (slot.state.load(std::memory_order_acquire) != kActive) continue;
        if (slot.folder)
            remove_folder(slot.path);
        else
            ::unlink(slot.path);
    }
    // SA_RESETHAND put the default action back, and the signal stays blocked until this
    // handler returns: raised again, it ends the process the way it would have.
    ::raise(signal);
    errno = saved_errno;
}

void install_handlers() {
    static std::once_flag once;
    std::call_once(once, [] {
        for (const int signal : kSignals) {
            struct sigaction old {};
            if (::sigaction(signal, nullptr, &old) != 0 || old.sa_handler != SIG_DFL) continue;
            struct sigaction action {};
            action.sa_handler = remove_and_reraise;
            sigfillset(&action.sa_mask);  // one cleanup at a time
            action.sa_flags = SA_RESETHAND;
            ::sigaction(signal, &action, nullptr);
        }
    });
}

}  // namespace

RemoveOnSignal::RemoveOnSignal(const std::filesystem::path& path, Kind kind) {
    const std::string text = path.string();
    if (text.size() >= sizeof Slot::path) throw Error(path.string() + ": path too long");
    for (size_t i = 0; i < g_slots.size() && slot_ < 0; ++i) {
        int expected = kFree;
        if (g_slots[i].state.compare_exchange_strong(expected, kClaimed)) slot_ = int(i);
    }
    if (slot_ < 0) throw Error(path.string() + ": too many outputs in progress");
    Slot& slot = g_slots[size_t(slot_)];
    std::memcpy(slot.path, text.c_str(), text.size() + 1);
    slot.folder = kind == Kind::Folder;
    install_handlers();
    slot.state.store(kActive, std::memory_order_release);
}

RemoveOnSignal::~RemoveOnSignal() {
    g_slots[size_t(slot_)].state.store(kFree, std::memory_order_release);
}

}  // namespace ds::capture
