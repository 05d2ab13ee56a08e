#pragma once
// Synthetic prepass output for the screen-space pass tests: a CPU ray caster writes exactly
// what a depth prepass would (depth at pixel centres in either convention, world normals
// encoded n * 0.5 + 0.5 as A2B10G10R10) for a scene of known geometry, with the matching
// FrameUniforms, and remembers which surface and world point each pixel shows, so a test can
// pick pixels by geometric fact ("floor, 5 cm from the wall").
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/passes/frame.h"

namespace ds::test {

struct Box {
    glm::vec3 min{0.0f}, max{0.0f};
};

// A square floor (y = 0, |x|, |z| <= floor_half_size, facing +Y) and boxes standing on it.
struct SyntheticScene {
    float floor_half_size = 10.0f;
    std::vector<Box> boxes;
};

struct SyntheticCamera {
    glm::vec3 eye{0.0f}, target{0.0f, 0.0f, -1.0f};
    float fov_y_degrees = 60.0f;
    float znear = 0.1f, zfar = 100.0f;
};

enum class Surface : uint8_t { Sky, Floor, Box };

struct PixelHit {
    Surface surface = Surface::Sky;
    glm::vec3 position{0.0f};  // world
    glm::vec3 normal{0.0f};    // world, unit
};

struct SyntheticFrame {
    uint32_t width = 0, height = 0;
    bool reverse_z = true;
    std::vector<float> depth;       // D32, row-major
    std::vector<uint32_t> normals;  // A2B10G10R10_UNORM_PACK32
    std::vector<PixelHit> hits;
    passes::FrameUniforms uniforms;

    const PixelHit& hit(uint32_t x, uint32_t y) const { return hits[size_t(y) * width + x]; }
    // The pixel whose centre shows `world` (to within a pixel), if it is in view.
    std::optional<glm::ivec2> pixel_of(const glm::vec3& world) const;
};

// `sun_direction`: towards the sun, world space (normalized here).
SyntheticFrame render_synthetic(const SyntheticScene& scene, const SyntheticCamera& camera,
                                uint32_t width, uint32_t height, bool reverse_z,
                                glm::vec3 sun_direction = {0.0f, 1.0f, 0.0f});

// The frame the AO and contact-shadow tests share: a floor and a wall 1.5 m high, 0.3 m
// thick, its front face the plane x = 0 (facing -X, towards the camera): a right-angle corner
// along z. The camera looks at it from above the floor on the -X side; the top rows show sky.
SyntheticScene corner_scene();
SyntheticCamera corner_camera();
inline constexpr float kWallThickness = 0.3f;
inline constexpr float kWallHeight = 1.5f;
inline constexpr float kWallHalfLength = 4.0f;

}  // namespace ds::test
