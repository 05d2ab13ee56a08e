#include "ui/camera_bookmarks.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "capture/file_output.h"
#include "capture/replay_info.h"
#include "renderer/common/error.h"

namespace ds::ui {
namespace {

using nlohmann::json;

constexpr const char* kFormat = "depthscope camera bookmarks";

// A bookmark from the file; false when it is not one (skipped, the rest kept).
bool read_bookmark(const json& j, CameraBookmark& out) {
    if (!j.is_object() || !j.contains("name") || !j["name"].is_string() || !j.contains("camera"))
        return false;
    out.name = j["name"].get<std::string>();
    return !capture::read_camera(j["camera"], out.camera).has_value();
}

}  // namespace

CameraBookmarks::CameraBookmarks(std::filesystem::path file) : file_(std::move(file)) {
    if (!file_.empty()) load();
}

void CameraBookmarks::load() {
    std::ifstream in(file_, std::ios::binary);
    if (!in) return;  // none saved yet
    std::ostringstream text;
    text << in.rdbuf();
    const json j = json::parse(text.str(), nullptr, /*allow_exceptions=*/false);
    if (j.is_discarded() || !j.is_object() || j.value("format", "") != kFormat ||
        !j.contains("scenes") || !j["scenes"].is_object()) {
        writable_ = false;
        error_ = file_.string() +
                 ": not depthscope's camera bookmarks; left as it is, "
                 "bookmarks of this session are not saved";
        return;
    }
    for (const auto& [scene, list] : j["scenes"].items()) {
        if (!list.is_array()) continue;
        for (const json& entry : list)
            if (CameraBookmark b; read_bookmark(entry, b)) by_scene_[scene].push_back(b);
    }
}

void CameraBookmarks::save() {
    if (file_.empty() || !writable_) return;
    json scenes = json::object();
    for (const auto& [scene, list] : by_scene_) {
        if (list.empty()) continue;
        json entries = json::array();
        for (const CameraBookmark& b : list)
            entries.push_back({{"name", b.name}, {"camera", capture::camera_json(b.camera)}});
        scenes[scene] = entries;
    }
    const json out = {{"format", kFormat}, {"scenes", scenes}};
    std::error_code ec;
    std::filesystem::create_directories(file_.parent_path(), ec);
    try {
        capture::write_file_atomically("camera bookmarks", file_, out.dump(2) + "\n");
        error_.clear();
    } catch (const Error& e) {
        error_ = e.what();
    }
}

const std::vector<CameraBookmark>& CameraBookmarks::of(const std::string& scene) const {
    static const std::vector<CameraBookmark> kNone;
    const auto it = by_scene_.find(scene);
    return it == by_scene_.end() ? kNone : it->second;
}

const scene::Camera* CameraBookmarks::find(const std::string& scene,
                                           const std::string& name) const {
    for (const CameraBookmark& b : of(scene))
        if (b.name == name) return &b.camera;
    return nullptr;
}

void CameraBookmarks::put(const std::string& scene, const std::string& name,
                          const scene::Camera& camera) {
    std::vector<CameraBookmark>& list = by_scene_[scene];
    const auto it = std::find_if(list.begin(), list.end(),
                                 [&](const CameraBookmark& b) { return b.name == name; });
    if (it != list.end())
        it->camera = camera;
    else
        list.push_back({name, camera});
    save();
}

void CameraBookmarks::remove(const std::string& scene, const std::string& name) {
    const auto it = by_scene_.find(scene);
    if (it == by_scene_.end()) return;
    std::erase_if(it->second, [&](const CameraBookmark& b) { return b.name == name; });
    save();
}

std::string bookmark_key(const scene::Scene& scene) {
    if (scene.source.rfind("builtin:", 0) == 0) return scene.source;
    std::error_code ec;
    const std::filesystem::path absolute = std::filesystem::absolute(scene.source, ec);
    return ec ? scene.source : absolute.lexically_normal().string();
}

}  // namespace ds::ui
