#pragma once
// Output that appears complete or not at all (DESIGN decision 8): files are written into a
// staging folder and moved into place by commit(). Without commit() the staging folder is
// removed, so a failed capture leaves nothing behind.
#include <filesystem>
#include <string>
#include <vector>

namespace ds::capture {

class OutputDir {
  public:
    // Throws ds::Error ("DIR: cannot create: …") when the folder cannot be made.
    explicit OutputDir(std::filesystem::path final_dir);
    ~OutputDir();
    OutputDir(const OutputDir&) = delete;
    OutputDir& operator=(const OutputDir&) = delete;

    // Where to write `name` now (inside the staging folder).
    std::filesystem::path staging_path(const std::string& name) const;
    const std::filesystem::path& staging_dir() const { return staging_; }
    const std::filesystem::path& final_dir() const { return final_; }

    // Moves every staged file to the final folder. Throws ds::Error on failure.
    void commit();

  private:
    std::filesystem::path final_;
    std::filesystem::path staging_;
    bool final_existed_ = false;
    bool committed_ = false;
};

// captures/YYYYmmdd-HHMMSS-SCENE under `root`, with -2, -3 … appended when taken.
std::filesystem::path default_capture_dir(const std::filesystem::path& root,
                                          const std::string& scene_name);

}  // namespace ds::capture
