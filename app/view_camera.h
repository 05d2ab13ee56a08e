#pragma once
// The view a command renders, from its options: --look-at (a camera at a point looking at
// another), --camera DIR (a capture folder's camera) or the scene's own camera. One place, so
// every command that takes these options reads them alike (today: diagnose).
#include "app/cli.h"
#include "renderer/scene/scene.h"

namespace ds::app {

// --look-at: at the eye, looking at the target, up as near +Y as the direction allows (+Z when
// looking straight up or down); the scene camera's field of view and near plane, the far plane
// pushed out to hold the whole scene from the eye.
scene::Camera look_at_camera(const LookAt& look_at, const scene::Scene& scene);

// The camera `o` names for `scene`; throws ds::Error for a --camera folder without a report.
scene::Camera view_camera(const Options& o, const scene::Scene& scene);

}  // namespace ds::app
