#pragma once
// The inspector's named camera bookmarks, per scene, kept in the config folder's cameras.json
// (ui/config.h) with the cameras exact (floats survive JSON's doubles), written whole through
// a temporary file and a rename at every change. A file that cannot be read as bookmarks is
// left as it is: the session's bookmarks are then not saved, and error() says why.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "renderer/scene/scene.h"

namespace ds::ui {

struct CameraBookmark {
    std::string name;
    scene::Camera camera;
};

class CameraBookmarks {
  public:
    // Reads `file`; an empty path keeps bookmarks for the session only.
    explicit CameraBookmarks(std::filesystem::path file = {});

    // A scene's bookmarks in the order they were added; `scene` is bookmark_key()'s.
    const std::vector<CameraBookmark>& of(const std::string& scene) const;
    const scene::Camera* find(const std::string& scene, const std::string& name) const;
    // Adds `camera` under `name` (replacing the scene's bookmark of that name) and saves.
    void put(const std::string& scene, const std::string& name, const scene::Camera& camera);
    // Removes the scene's bookmark `name` (if any) and saves.
    void remove(const std::string& scene, const std::string& name);

    const std::filesystem::path& file() const { return file_; }
    // Why the file could not be read or written, "" when all is well.
    const std::string& error() const { return error_; }

  private:
    void load();
    void save();

    std::filesystem::path file_;
    std::map<std::string, std::vector<CameraBookmark>> by_scene_;
    std::string error_;
    bool writable_ = true;  // false: the file holds something else, never overwritten
};

// The scene a bookmark belongs to: "builtin:NAME" for a built-in scene, else the file's
// absolute path (the same file whatever folder the inspector started in).
std::string bookmark_key(const scene::Scene& scene);

}  // namespace ds::ui
