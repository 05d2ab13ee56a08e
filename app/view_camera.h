#pragma once
// The view a command renders, from its options: --camera NAME|INDEX (a camera node of the
// scene), --look-at (a camera at a point looking at another), diagnose's --camera-of DIR (a
// capture folder's camera) or the scene's own camera. One place, so every command that takes
// these options (capture, bench, pixel, replay, view, diagnose) reads them alike, and a bad
// choice is a usage error before anything is rendered or written.
#include <optional>
#include <string>

#include "app/cli.h"
#include "renderer/scene/scene.h"

namespace ds::app {

// --look-at: at the eye, looking at the target, up +Y (parse_look_at refused a view within 1
// degree of straight up or down); look_at.fov or the scene camera's field of view, the scene
// camera's near plane, its far plane pushed out to hold the whole scene from the eye.
scene::Camera look_at_camera(const LookAt& look_at, const scene::Scene& scene);

// --camera SPEC: the scene's camera node SPEC names (all digits: an index into scene.cameras,
// as `depthscope cameras` prints it; else a node name, matched exactly), placed. Throws
// UsageError naming SPEC and listing the usable cameras (or saying there are none) for an
// unknown one, and for an orthographic one or one whose node leaves no view direction.
scene::Camera node_camera(const std::string& spec, const scene::Scene& scene);

// The camera --camera or --look-at names, none when neither is given.
std::optional<scene::Camera> chosen_camera(const Options& o, const scene::Scene& scene);

// The camera `o` names for `scene` (--camera-of too), else scene.camera; throws UsageError as
// above, ds::Error for a --camera-of folder without a report.
scene::Camera view_camera(const Options& o, const scene::Scene& scene);

}  // namespace ds::app
