#include "ui/shader_watch.h"

#include <system_error>

namespace ds::ui {

ShaderWatch::ShaderWatch(std::filesystem::path root, std::chrono::milliseconds interval)
    : root_(std::move(root)), interval_(interval) {
    stamp_ = scan();
    next_poll_ = std::chrono::steady_clock::now() + interval_;
}

ShaderWatch::Stamp ShaderWatch::scan() const {
    Stamp s;
    std::error_code ec;
    for (auto it = std::filesystem::recursive_directory_iterator(root_, ec);
         !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec)) {
        if (!it->is_regular_file(ec)) continue;
        ++s.files;
        const auto t = it->last_write_time(ec);
        if (!ec && t > s.newest) s.newest = t;
    }
    return s;
}

bool ShaderWatch::changed() {
    const auto now = std::chrono::steady_clock::now();
    if (now < next_poll_) return false;
    next_poll_ = now + interval_;
    const Stamp s = scan();
    if (s == stamp_) return false;
    stamp_ = s;
    return true;
}

}  // namespace ds::ui
