#include "capture/file_output.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "capture/signal_cleanup.h"
#include "renderer/common/error.h"
#include "renderer/common/quoted.h"

namespace fs = std::filesystem;

namespace ds::capture {
namespace {

[[noreturn]] void fail_errno(const fs::path& path, const char* what, int error) {
    throw Error(escaped(path.string()) + ": " + what + ": " + std::strerror(error));
}

// Why an existing node at `path` must not be written over; empty when it is a regular file.
std::string refusal(const struct stat& st) {
    if (S_ISREG(st.st_mode)) return {};
    if (S_ISDIR(st.st_mode)) return "is a directory";
    if (S_ISLNK(st.st_mode)) return "is a symbolic link";
    if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) return "is a device node";
    if (S_ISFIFO(st.st_mode)) return "is a FIFO";
    if (S_ISSOCK(st.st_mode)) return "is a socket";
    return "is not a regular file";
}

// The folder a file named `path` lands in ("." for a bare name).
fs::path folder_of(const fs::path& path) {
    const fs::path parent = path.parent_path();
    return parent.empty() ? fs::path(".") : parent;
}

}  // namespace

void write_all(int fd, std::string_view data, const fs::path& path) {
    size_t done = 0;
    while (done < data.size()) {
        const ssize_t n = ::write(fd, data.data() + done, data.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) fail_errno(path, "cannot write", errno);
        if (n == 0) fail_errno(path, "cannot write", EIO);  // no progress: never loop forever
        done += size_t(n);
    }
}

void write_new_file(const fs::path& path, std::string_view data) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) fail_errno(path, "cannot create", errno);
    try {
        write_all(fd, data, path);
    } catch (...) {
        ::close(fd);
        ::unlink(path.c_str());
        throw;
    }
    // close() reports what a delayed write-back found (NFS, quotas); it counts too.
    if (::close(fd) != 0) {
        const int error = errno;
        ::unlink(path.c_str());
        fail_errno(path, "cannot write", error);
    }
}

void check_output_file(std::string_view option, const fs::path& path) {
    const std::string subject = std::string(option) + " " + escaped(path.string());
    struct stat st {};
    if (::lstat(path.c_str(), &st) == 0) {
        const std::string why = refusal(st);
        if (!why.empty()) throw Error(subject + ": " + why + " (only a regular file is replaced)");
        return;
    }
    if (errno != ENOENT) throw Error(subject + ": " + std::strerror(errno));
    const fs::path folder = folder_of(path);
    if (::stat(folder.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
        throw Error(subject + ": no folder " + escaped(folder.string()));
}

void write_file_atomically(std::string_view option, const fs::path& path, std::string_view data) {
    const fs::path temp = path.string() + ".tmp-" + std::to_string(::getpid());
    const RemoveOnSignal guard(temp, RemoveOnSignal::Kind::File);
    ::unlink(temp.c_str());  // a leftover of an earlier process with this id
    write_new_file(temp, data);
    // Checked again: the target may have become something else while the work ran.
    try {
        check_output_file(option, path);
    } catch (...) {
        ::unlink(temp.c_str());
        throw;
    }
    if (::rename(temp.c_str(), path.c_str()) != 0) {
        const int error = errno;
        ::unlink(temp.c_str());
        fail_errno(path, "cannot move into place", error);
    }
}

}  // namespace ds::capture
