#include "renderer/scene/gltf_source.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "renderer/scene/import_limits.h"
#include "renderer/scene/import_util.h"

namespace ds::scene::detail {
namespace {

namespace fs = std::filesystem;

std::string errno_text(int error) {
    return std::strerror(error);
}

std::string size_text(uint64_t bytes) {
    return std::to_string(bytes) + " bytes";
}

// Refuses anything but a regular file of at most kMaxFileBytes.
void check_status(const struct stat& st) {
    if (S_ISDIR(st.st_mode)) fail("is a directory, not a regular file");
    if (S_ISFIFO(st.st_mode)) fail("is a FIFO, not a regular file");
    if (S_ISCHR(st.st_mode)) fail("is a character device, not a regular file");
    if (S_ISBLK(st.st_mode)) fail("is a block device, not a regular file");
    if (S_ISSOCK(st.st_mode)) fail("is a socket, not a regular file");
    if (!S_ISREG(st.st_mode)) fail("is not a regular file");
    if (static_cast<uint64_t>(st.st_size) > limits::kMaxFileBytes)
        fail("is " + size_text(static_cast<uint64_t>(st.st_size)) + ", more than the limit of " +
             size_text(limits::kMaxFileBytes));
}

uint64_t stat_checked(const fs::path& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0)
        fail(errno == ENOENT || errno == ENOTDIR ? "no such file" : errno_text(errno));
    check_status(st);
    return static_cast<uint64_t>(st.st_size);
}

class Fd {
  public:
    explicit Fd(int fd) : fd_(fd) {}
    ~Fd() {
        if (fd_ >= 0) ::close(fd_);
    }
    Fd(const Fd&) = delete;
    Fd& operator=(const Fd&) = delete;
    int get() const { return fd_; }

  private:
    int fd_;
};

bool has_nul(const std::string& text) {
    return text.find('\0') != std::string::npos;
}

unsigned char from_hex(unsigned char c) {  // as tinygltf's dlib::from_hex: non-hex is 0
    if (c >= '0' && c <= '9') return static_cast<unsigned char>(c - '0');
    if (c >= 'a' && c <= 'f') return static_cast<unsigned char>(c - 'a' + 10);
    if (c >= 'A' && c <= 'F') return static_cast<unsigned char>(c - 'A' + 10);
    return 0;
}

std::string strip_dot_slash(std::string uri) {
    while (uri.starts_with("./")) uri.erase(0, 2);
    return uri;
}

}  // namespace

std::string read_regular_file(const fs::path& path) {
    stat_checked(path);  // no open() of a FIFO or device at all
    const Fd fd(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC));
    if (fd.get() < 0) fail("cannot open: " + errno_text(errno));
    struct stat st {};
    if (::fstat(fd.get(), &st) != 0) fail(errno_text(errno));
    check_status(st);  // replaced between stat and open
    std::string bytes(static_cast<size_t>(st.st_size), '\0');
    size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t got = ::read(fd.get(), bytes.data() + done, bytes.size() - done);
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) fail("cannot read: " + errno_text(errno));
        if (got == 0) fail("file shrank while being read");
        done += static_cast<size_t>(got);
    }
    return bytes;
}

fs::path DiskSource::resolve(const std::string& uri) const {
    if (uri.empty()) fail("empty uri");
    if (has_nul(uri)) fail("uri holds a NUL byte");
    return base_dir_ / uri;  // an absolute uri stays absolute
}

uint64_t DiskSource::check(const std::string& uri) const {
    return stat_checked(resolve(uri));
}

std::string DiskSource::read(const std::string& uri) const {
    return read_regular_file(resolve(uri));
}

const std::string& MemorySource::find(const std::string& uri) const {
    if (uri.empty()) fail("empty uri");
    const auto it = files_.find(strip_dot_slash(uri));
    if (it == files_.end()) fail("no such file");
    if (it->second.size() > limits::kMaxFileBytes)
        fail("is " + size_text(it->second.size()) + ", more than the limit");
    return it->second;
}

uint64_t MemorySource::check(const std::string& uri) const {
    return find(uri).size();
}

std::string MemorySource::read(const std::string& uri) const {
    return find(uri);
}

std::string decode_uri(const std::string& uri) {
    std::string result;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '+') {
            result += ' ';
        } else if (uri[i] == '%' && uri.size() > i + 2) {
            const auto hi = from_hex(static_cast<unsigned char>(uri[i + 1]));
            const auto lo = from_hex(static_cast<unsigned char>(uri[i + 2]));
            result += static_cast<char>((hi << 4) | lo);
            i += 2;
        } else {
            result += uri[i];
        }
    }
    return result;
}

tinygltf::FsCallbacks FsBridge::callbacks() {
    tinygltf::FsCallbacks fs{};
    // Every path "exists": ReadWholeFile makes the checks and names what is wrong.
    fs.FileExists = [](const std::string&, void*) { return true; };
    fs.ExpandFilePath = [](const std::string& path, void*) { return path; };
    fs.ReadWholeFile = [](std::vector<unsigned char>* out, std::string* err,
                          const std::string& path, void* user) {
        auto* bridge = static_cast<FsBridge*>(user);
        try {
            const std::string bytes = bridge->source->read(path);
            out->assign(bytes.begin(), bytes.end());
            return true;
        } catch (const InputError& e) {
            const std::string what = "uri " + quote_value(path) + ": " + e.what();
            if (bridge->error.empty()) bridge->error = what;
            if (err) *err += what;
            return false;
        }
    };
    fs.WriteWholeFile = [](std::string* err, const std::string&, const std::vector<unsigned char>&,
                           void*) {
        if (err) *err += "the importer writes no files";
        return false;
    };
    fs.user_data = this;
    return fs;
}

}  // namespace ds::scene::detail
