#include "ui/camera_bookmarks.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

namespace ds::ui {
namespace {

using nlohmann::json;

constexpr const char* kFormat = "depthscope camera bookmarks";

json bookmark_vec3(const glm::vec3& v) {
    return {double(v.x), double(v.y), double(v.z)};
}

json bookmark_camera_json(const scene::Camera& c) {
    return {{"position", bookmark_vec3(c.position)},
            {"forward", bookmark_vec3(c.forward)},
            {"up", bookmark_vec3(c.up)},
            {"yfov", double(c.yfov)},
            {"znear", double(c.znear)},
            {"zfar", double(c.zfar)}};
}

bool read_bookmark_vec3(const json& j, glm::vec3& out) {
    if (!j.is_array() || j.size() != 3) return false;
    for (int i = 0; i < 3; ++i) {
        if (!j[size_t(i)].is_number()) return false;
        out[i] = j[size_t(i)].get<float>();
    }
    return true;
}

bool read_bookmark_float(const json& j, float& out) {
    if (!j.is_number()) return false;
    out = j.get<float>();
    return true;
}

// A bookmark from the file; false when it is not one (skipped, the rest kept).
bool read_bookmark(const json& j, CameraBookmark& out) {
    if (!j.is_object() || !j.contains("name") || !j["name"].is_string() || !j.contains("camera"))
        return false;
    out.name = j["name"].get<std::string>();
    const json& c = j["camera"];
    return c.is_object() && read_bookmark_vec3(c.value("position", json()), out.camera.position) &&
           read_bookmark_vec3(c.value("forward", json()), out.camera.forward) &&
           read_bookmark_vec3(c.value("up", json()), out.camera.up) &&
           read_bookmark_float(c.value("yfov", json()), out.camera.yfov) &&
           read_bookmark_float(c.value("znear", json()), out.camera.znear) &&
           read_bookmark_float(c.value("zfar", json()), out.camera.zfar);
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
            entries.push_back({{"name", b.name}, {"camera", bookmark_camera_json(b.camera)}});
        scenes[scene] = entries;
    }
    const json out = {{"format", kFormat}, {"scenes", scenes}};
    std::error_code ec;
    std::filesystem::create_directories(file_.parent_path(), ec);
    const std::filesystem::path temp = file_.string() + ".tmp";
    {
        std::ofstream f(temp, std::ios::trunc);
        f << out.dump(2) << '\n';
        if (!f.flush()) {
            error_ = temp.string() + ": cannot write";
            return;
        }
    }
    std::filesystem::rename(temp, file_, ec);
    error_ = ec ? file_.string() + ": " + ec.message() : std::string();
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
