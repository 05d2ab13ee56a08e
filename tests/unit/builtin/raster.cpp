#include "raster.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ds::test {

namespace {

struct ScreenVertex {
    glm::vec2 p;  // pixels, row 0 at the top
    float inv_z;  // 1 / linear depth, interpolates linearly in screen space
};

float edge(const glm::vec2& a, const glm::vec2& b, const glm::vec2& p) {
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// Keeps the part of a view-space polygon in front of the near plane (z <= -znear).
std::vector<glm::vec3> clip_near(const std::vector<glm::vec3>& poly, float znear) {
    std::vector<glm::vec3> out;
    for (size_t i = 0; i < poly.size(); ++i) {
        const glm::vec3& a = poly[i];
        const glm::vec3& b = poly[(i + 1) % poly.size()];
        const float da = -a.z - znear, db = -b.z - znear;  // >= 0: inside
        if (da >= 0.0f) out.push_back(a);
        if ((da >= 0.0f) != (db >= 0.0f)) out.push_back(a + (b - a) * (da / (da - db)));
    }
    return out;
}

void raster_triangle(Coverage& c, int tri, const ScreenVertex& a, const ScreenVertex& b,
                     const ScreenVertex& v2) {
    const float area = edge(a.p, b.p, v2.p);
    if (std::abs(area) < 1e-12f) return;
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.p.x, b.p.x, v2.p.x}))));
    const int x1 =
        std::min(c.width - 1, static_cast<int>(std::ceil(std::max({a.p.x, b.p.x, v2.p.x}))));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.p.y, b.p.y, v2.p.y}))));
    const int y1 =
        std::min(c.height - 1, static_cast<int>(std::ceil(std::max({a.p.y, b.p.y, v2.p.y}))));
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
            // Sample a hair off the pixel centre so edges shared by two triangles (grid-aligned
            // walls seen straight on) are never counted twice.
            const glm::vec2 p(static_cast<float>(x) + 0.5f + 1.7e-4f,
                              static_cast<float>(y) + 0.5f + 3.1e-4f);
            float w0 = edge(b.p, v2.p, p), w1 = edge(v2.p, a.p, p), w2 = edge(a.p, b.p, p);
            if (area < 0.0f) {
                w0 = -w0;
                w1 = -w1;
                w2 = -w2;
            }
            if (w0 < 0.0f || w1 < 0.0f || w2 < 0.0f) continue;
            const size_t i = static_cast<size_t>(y) * static_cast<size_t>(c.width) + x;
            ++c.fragments[i];
            const float s = std::abs(area);
            const float inv_z = (w0 * a.inv_z + w1 * b.inv_z + w2 * v2.inv_z) / s;
            const float depth = 1.0f / inv_z;
            if (depth < c.depth[i]) {
                c.depth[i] = depth;
                c.nearest[i] = tri;
            }
        }
    }
}

}  // namespace

uint64_t Coverage::total_fragments() const {
    uint64_t n = 0;
    for (uint32_t f : fragments) n += f;
    return n;
}

uint64_t Coverage::covered_pixels() const {
    return static_cast<uint64_t>(
        std::count_if(fragments.begin(), fragments.end(), [](uint32_t f) { return f > 0; }));
}

double Coverage::depth_complexity() const {
    const uint64_t covered = covered_pixels();
    return covered ? static_cast<double>(total_fragments()) / static_cast<double>(covered) : 0.0;
}

Coverage rasterise(const std::vector<WorldTriangle>& tris, const ViewCamera& cam,
                   const RasterOptions& opt) {
    Coverage c;
    c.width = opt.width;
    c.height = opt.height;
    const size_t n = static_cast<size_t>(opt.width) * static_cast<size_t>(opt.height);
    c.fragments.assign(n, 0);
    c.nearest.assign(n, -1);
    c.depth.assign(n, std::numeric_limits<float>::infinity());
    const float ty = std::tan(cam.yfov * 0.5f), tx = ty * cam.aspect;
    for (size_t t = 0; t < tris.size(); ++t) {
        std::vector<glm::vec3> v(3);
        for (int k = 0; k < 3; ++k) v[k] = glm::vec3(cam.view * glm::vec4(tris[t].p[k], 1.0f));
        const glm::vec3 normal = glm::cross(v[1] - v[0], v[2] - v[0]);
        const bool front = glm::dot(normal, -v[0]) > 0.0f;  // counter-clockwise seen from eye
        if (opt.cull_back_faces && !tris[t].double_sided && !front) continue;
        const std::vector<glm::vec3> poly = clip_near(v, cam.znear);
        if (poly.size() < 3) continue;
        std::vector<ScreenVertex> s;
        for (const glm::vec3& p : poly) {
            const float ndc_x = p.x / -p.z / tx, ndc_y = p.y / -p.z / ty;
            s.push_back({{(ndc_x * 0.5f + 0.5f) * static_cast<float>(opt.width),
                          (0.5f - ndc_y * 0.5f) * static_cast<float>(opt.height)},
                         1.0f / -p.z});
        }
        for (size_t k = 1; k + 1 < s.size(); ++k) {
            raster_triangle(c, static_cast<int>(t), s[0], s[k], s[k + 1]);
        }
    }
    return c;
}

}  // namespace ds::test
