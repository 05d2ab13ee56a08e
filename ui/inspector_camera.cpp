// The Camera panel's actions: the scene's camera nodes, "fit inside" and named bookmarks
// (ui/camera_bookmarks.h). Each puts the camera controller at a view; the next frame follows.
#include "renderer/scene/fit_inside.h"
#include "ui/inspector.h"

namespace ds::ui {

void Inspector::go_to_camera(size_t index) {
    if (index < scene_.cameras.size() && scene_.cameras[index].camera)
        camera_.reset(*scene_.cameras[index].camera);
}

void Inspector::fit_inside() {
    camera_.reset(scene::fit_inside(scene_, camera_.camera()));
}

void Inspector::add_bookmark(const std::string& name) {
    // One line of the panel's list: trimmed, control characters as spaces.
    std::string clean;
    for (char c : name) clean += static_cast<unsigned char>(c) < 0x20 ? ' ' : c;
    const size_t first = clean.find_first_not_of(' ');
    if (first == std::string::npos) return;  // the panel says a name is needed
    clean = clean.substr(first, clean.find_last_not_of(' ') - first + 1);
    bookmarks_.put(bookmark_key(scene_), clean, camera_.camera());
}

}  // namespace ds::ui
