#pragma once
// The inspector's camera: orbit (left drag), pan (middle drag), dolly (wheel), fly (right drag
// with WASD / QE, shift for speed), F frames the scene's content (scene::content_bounds: not
// a ground or backdrop that dwarfs it). Pure math on scene::Camera; the viewer panel turns
// ImGui input into a CameraInput.
#include <glm/glm.hpp>

#include "renderer/scene/scene.h"

namespace ds::ui {

struct CameraInput {
    glm::vec2 orbit{0.0f};  // pixels dragged with the left button
    glm::vec2 pan{0.0f};    // pixels dragged with the middle button
    float dolly = 0.0f;     // wheel notches (positive: closer)
    glm::vec2 look{0.0f};   // pixels dragged with the right button (fly)
    glm::vec3 move{0.0f};   // fly: x right (D - A), y up (E - Q), z forward (W - S)
    bool fast = false;      // shift
    bool frame = false;     // F
    float dt = 1.0f / 60.0f;
    float viewport_height = 720.0f;  // pixels, for pan speed
    bool any() const;
};

class CameraController {
  public:
    // Starts from `camera`, orbiting around the centre of `content` (what F frames; its size
    // sets the fly speed).
    void reset(const scene::Camera& camera, const scene::Bounds& content);
    // Back to `camera` (the scene's own), with the same content.
    void reset(const scene::Camera& camera) { reset(camera, bounds_); }
    // Returns true when the camera moved (a camera cut is not needed: temporal passes follow).
    bool update(const CameraInput& input);
    const scene::Camera& camera() const { return camera_; }

  private:
    void frame_scene();

    scene::Camera camera_;
    scene::Bounds bounds_;
    glm::vec3 target_{0.0f};
    float distance_ = 5.0f;
    float scene_size_ = 1.0f;  // the content's diagonal
};

}  // namespace ds::ui
