#include "tests/gpu/screen_space/synthetic_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

namespace ds::test {
namespace {

struct Ray {
    glm::vec3 origin, direction;
};

// Vulkan clip space: y down, depth 0..1 (forward-Z) or 1..0 (reverse-Z), right-handed view.
glm::mat4 projection(const SyntheticCamera& c, float aspect, bool reverse_z) {
    const float f = 1.0f / std::tan(glm::radians(c.fov_y_degrees) * 0.5f);
    const float n = c.znear, z = c.zfar;
    glm::mat4 p(0.0f);
    p[0][0] = f / aspect;
    p[1][1] = -f;
    p[2][3] = -1.0f;
    p[2][2] = reverse_z ? n / (z - n) : z / (n - z);
    p[3][2] = reverse_z ? n * z / (z - n) : n * z / (n - z);
    return p;
}

uint32_t encode_normal(const glm::vec3& n) {
    const auto channel = [](float v) {
        return uint32_t(std::lround(std::clamp(v * 0.5f + 0.5f, 0.0f, 1.0f) * 1023.0f));
    };
    return channel(n.x) | channel(n.y) << 10 | channel(n.z) << 20 | 3u << 30;
}

// Nearest hit with the floor or a box (slab test; the entry face gives the normal).
std::optional<PixelHit> trace(const SyntheticScene& scene, const Ray& ray) {
    float best = std::numeric_limits<float>::max();
    PixelHit hit;
    if (ray.direction.y < 0.0f) {
        const float t = -ray.origin.y / ray.direction.y;
        const glm::vec3 p = ray.origin + t * ray.direction;
        if (std::abs(p.x) <= scene.floor_half_size && std::abs(p.z) <= scene.floor_half_size) {
            best = t;
            hit = {Surface::Floor, p, {0.0f, 1.0f, 0.0f}};
        }
    }
    for (const Box& box : scene.boxes) {
        float t_near = -std::numeric_limits<float>::max(), t_far = best;
        int axis = -1;
        for (int a = 0; a < 3; ++a) {
            if (std::abs(ray.direction[a]) < 1e-9f) {
                if (ray.origin[a] < box.min[a] || ray.origin[a] > box.max[a]) t_far = -1.0f;
                continue;
            }
            float t0 = (box.min[a] - ray.origin[a]) / ray.direction[a];
            float t1 = (box.max[a] - ray.origin[a]) / ray.direction[a];
            if (t0 > t1) std::swap(t0, t1);
            if (t0 > t_near) t_near = t0, axis = a;
            t_far = std::min(t_far, t1);
        }
        if (axis < 0 || t_near > t_far || t_near <= 0.0f || t_near >= best) continue;
        best = t_near;
        glm::vec3 n(0.0f);
        n[axis] = ray.direction[axis] > 0.0f ? -1.0f : 1.0f;
        hit = {Surface::Box, ray.origin + t_near * ray.direction, n};
    }
    if (best == std::numeric_limits<float>::max()) return std::nullopt;
    return hit;
}

}  // namespace

SyntheticScene corner_scene() {
    SyntheticScene s;
    s.boxes.push_back(
        {{0.0f, 0.0f, -kWallHalfLength}, {kWallThickness, kWallHeight, kWallHalfLength}});
    return s;
}

SyntheticCamera corner_camera() {
    SyntheticCamera c;
    c.eye = {-3.0f, 2.5f, 2.0f};
    c.target = {0.0f, 0.3f, 0.0f};
    return c;
}

SyntheticFrame render_synthetic(const SyntheticScene& scene, const SyntheticCamera& camera,
                                uint32_t width, uint32_t height, bool reverse_z,
                                glm::vec3 sun_direction) {
    SyntheticFrame f;
    f.width = width;
    f.height = height;
    f.reverse_z = reverse_z;
    const glm::mat4 view = glm::lookAt(camera.eye, camera.target, glm::vec3(0, 1, 0));
    const glm::mat4 proj = projection(camera, float(width) / float(height), reverse_z);
    passes::FrameUniforms& u = f.uniforms;
    u.view = view;
    u.projection = proj;
    u.view_projection = proj * view;
    u.inverse_view_projection = glm::inverse(u.view_projection);
    u.inverse_projection = glm::inverse(proj);
    u.previous_view_projection = u.view_projection;  // a static camera
    u.camera_position = glm::vec4(camera.eye, 1.0f);
    u.sun_direction = glm::vec4(glm::normalize(sun_direction), 0.0f);
    u.viewport = {float(width), float(height), 1.0f / float(width), 1.0f / float(height)};
    u.depth_params = {camera.znear, camera.zfar, reverse_z ? 1.0f : 0.0f, 1.0f};
    u.flags = {reverse_z ? passes::kFrameReverseZ : 0u, 0u, 0u, 0u};

    const glm::mat4 inverse_view = glm::inverse(view);
    const float tan_half = std::tan(glm::radians(camera.fov_y_degrees) * 0.5f);
    const float aspect = float(width) / float(height);
    const float far_depth = reverse_z ? 0.0f : 1.0f;
    f.depth.assign(size_t(width) * height, far_depth);
    f.normals.assign(size_t(width) * height, 0u);
    f.hits.assign(size_t(width) * height, PixelHit{});
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            const float ndc_x = (float(x) + 0.5f) / float(width) * 2.0f - 1.0f;
            const float ndc_y = (float(y) + 0.5f) / float(height) * 2.0f - 1.0f;
            const glm::vec3 dir_view{ndc_x * tan_half * aspect, -ndc_y * tan_half, -1.0f};
            const glm::vec3 dir = glm::normalize(glm::vec3(inverse_view * glm::vec4(dir_view, 0)));
            const auto hit = trace(scene, {camera.eye, dir});
            if (!hit) continue;
            const glm::vec4 clip = u.view_projection * glm::vec4(hit->position, 1.0f);
            const float d = clip.z / clip.w;
            if (d < 0.0f || d > 1.0f) continue;  // beyond the far plane: sky
            const size_t i = size_t(y) * width + x;
            f.depth[i] = d;
            f.normals[i] = encode_normal(hit->normal);
            f.hits[i] = *hit;
        }
    }
    return f;
}

std::optional<glm::ivec2> SyntheticFrame::pixel_of(const glm::vec3& world) const {
    const glm::vec4 clip = uniforms.view_projection * glm::vec4(world, 1.0f);
    if (clip.w <= 0.0f) return std::nullopt;
    const glm::vec2 uv = glm::vec2(clip) / clip.w * 0.5f + 0.5f;
    const glm::ivec2 p{int(std::floor(uv.x * float(width))), int(std::floor(uv.y * float(height)))};
    if (p.x < 0 || p.y < 0 || p.x >= int(width) || p.y >= int(height)) return std::nullopt;
    return p;
}

}  // namespace ds::test
