#pragma once
// Automatic shader reload: polls the shader folder's files (the newest modification time and
// the file count) at most every `interval`; changed() says when they moved since last time.
#include <chrono>
#include <filesystem>

namespace ds::ui {

class ShaderWatch {
  public:
    explicit ShaderWatch(std::filesystem::path root,
                         std::chrono::milliseconds interval = std::chrono::milliseconds(500));
    bool changed();  // cheap between polls

  private:
    struct Stamp {
        // min(), not {}: libstdc++'s file_clock epoch lies in the future (today is negative).
        std::filesystem::file_time_type newest = std::filesystem::file_time_type::min();
        size_t files = 0;
        bool operator==(const Stamp&) const = default;
    };
    Stamp scan() const;

    std::filesystem::path root_;
    std::chrono::milliseconds interval_;
    std::chrono::steady_clock::time_point next_poll_{};
    Stamp stamp_;
};

}  // namespace ds::ui
