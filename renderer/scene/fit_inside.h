#pragma once
// "Fit inside", the inspector's view for interiors: a camera at an open spot inside the scene's
// bounds, looking along their longest horizontal axis. Pure CPU, rays against the scene's
// triangles (no acceleration structure: three rays, each instance's box tested first).
#include <vector>

#include "renderer/scene/scene.h"

namespace ds::scene {

// Where a ray met a triangle: at origin + t * direction; `front` when it met the triangle's
// front face (counter-clockwise as seen from the ray's origin, in world space), `double_sided`
// when the triangle's material is.
struct RayHit {
    float t = 0.0f;
    bool front = false;
    bool double_sided = false;
};

// Every triangle the ray meets for 0 < t <= t_max, unsorted.
std::vector<RayHit> cast_ray(const Scene& scene, const glm::vec3& origin,
                             const glm::vec3& direction, float t_max);

// A person's eye height in metres, glTF's unit: how far above a floor fit_inside puts the eye.
inline constexpr float kEyeHeight = 1.6f;

// The eye at the bounds' centre in X and Z, at a height with free space: on the vertical line
// there, the tallest open gap — above a surface that faces up (or is double-sided), below one
// that faces down (or the bounds' top) — kEyeHeight above its floor, or half way up a lower
// gap; the bounds' centre when the line meets nothing. It looks along the bounds' longest
// horizontal axis, towards the side with more free space (-X or -Z on a tie), up +Y. yfov
// and znear are `like`'s; zfar holds the whole scene from the eye.
Camera fit_inside(const Scene& scene, const Camera& like);

}  // namespace ds::scene
