// Smoke render of the seed frame on the real device (lavapipe in CI) with validation on: a
// ground plane and a textured cube, checked against facts computed from the scene itself.
#include <stb/stb_image_write.h>

#include <cmath>
#include <cstdio>
#include <set>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "renderer/common/error.h"
#include "renderer/renderer.h"

namespace {

using namespace ds;

// Quad in the XZ plane at height y, facing +Y, side `size`, counter-clockwise from above.
scene::Mesh plane_mesh(float size, uint32_t material) {
    scene::Mesh m;
    m.name = "ground";
    m.material = material;
    const float h = size * 0.5f;
    const glm::vec3 n{0, 1, 0};
    const glm::vec4 t{1, 0, 0, 1};
    m.vertices = {{{-h, 0, h}, n, {0, 0}, t},
                  {{h, 0, h}, n, {size, 0}, t},
                  {{h, 0, -h}, n, {size, size}, t},
                  {{-h, 0, -h}, n, {0, size}, t}};
    m.indices = {0, 1, 2, 0, 2, 3};
    for (const auto& v : m.vertices) m.bounds.extend(v.position);
    return m;
}

// Unit cube centred on the origin: 6 faces x 4 vertices, outward normals, CCW from outside.
scene::Mesh cube_mesh(uint32_t material) {
    scene::Mesh m;
    m.name = "cube";
    m.material = material;
    const glm::vec3 normals[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                  {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    for (const glm::vec3& n : normals) {
        // u, v span the face so that u x v = n (counter-clockwise seen from outside).
        const glm::vec3 u =
            std::abs(n.y) > 0.5f ? glm::vec3(1, 0, 0) : glm::cross(glm::vec3(0, 1, 0), n);
        const glm::vec3 v = glm::cross(n, u);
        const uint32_t base = uint32_t(m.vertices.size());
        const glm::vec2 uv[4] = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
        const glm::vec2 corner[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (int i = 0; i < 4; ++i) {
            const glm::vec3 p = 0.5f * (n + corner[i].x * u + corner[i].y * v);
            m.vertices.push_back({p, n, uv[i], glm::vec4(u, 1.0f)});
        }
        for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + i);
    }
    for (const auto& vtx : m.vertices) m.bounds.extend(vtx.position);
    return m;
}

scene::Image checker(uint32_t size, uint32_t cells) {
    scene::Image img;
    img.name = "checker";
    img.width = img.height = size;
    img.srgb = true;
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x) {
            const bool odd = ((x * cells / size) + (y * cells / size)) % 2;
            const uint8_t c[4] = {uint8_t(odd ? 230 : 200), uint8_t(odd ? 60 : 170),
                                  uint8_t(odd ? 40 : 60), 255};
            img.rgba8.insert(img.rgba8.end(), c, c + 4);
        }
    return img;
}

scene::Scene smoke_scene() {
    scene::Scene s;
    s.name = "smoke";
    scene::Material ground;
    ground.name = "ground";
    ground.base_color_factor = {0.55f, 0.6f, 0.5f, 1.0f};
    ground.metallic_factor = 0.0f;
    ground.roughness_factor = 0.9f;
    scene::Material cube;
    cube.name = "checker";
    cube.metallic_factor = 0.0f;
    cube.roughness_factor = 0.5f;
    cube.base_color.texture = 0;
    s.materials = {ground, cube};
    s.images = {checker(64, 4)};
    s.samplers = {scene::Sampler{}};
    s.textures = {scene::Texture{0, 0}};
    s.meshes = {plane_mesh(6.0f, 0), cube_mesh(1)};
    s.instances = {{0, glm::mat4(1.0f), "plane"},
                   {1, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.5f, 0.0f)), "cube"}};
    s.draw_groups = {{0, scene::AlphaMode::Opaque, false, 0, 1},
                     {1, scene::AlphaMode::Opaque, false, 1, 1}};
    for (const auto& inst : s.instances) {
        const auto& b = s.meshes[inst.mesh].bounds;
        s.bounds.extend(glm::vec3(inst.world * glm::vec4(b.min, 1)));
        s.bounds.extend(glm::vec3(inst.world * glm::vec4(b.max, 1)));
    }
    s.camera.position = {2.6f, 2.2f, 3.4f};
    s.camera.forward = glm::normalize(glm::vec3(0, 0.3f, 0) - s.camera.position);
    s.camera.up = glm::normalize(
        glm::cross(glm::cross(s.camera.forward, glm::vec3(0, 1, 0)), s.camera.forward));
    s.camera.znear = 0.05f;
    s.camera.zfar = 50.0f;
    return s;
}

// Pixels whose centre lies inside any triangle of the scene, projected on the CPU with the
// same camera: what the rasterizer must cover (top-left rules aside).
size_t expected_coverage(const scene::Scene& s, uint32_t w, uint32_t h) {
    const glm::mat4 vp =
        glm::perspective(s.camera.yfov, float(w) / float(h), s.camera.znear, s.camera.zfar) *
        s.camera.view();
    std::vector<glm::vec2> tri_px;
    for (const auto& inst : s.instances) {
        const auto& mesh = s.meshes[inst.mesh];
        for (uint32_t idx : mesh.indices) {
            const glm::vec4 c = vp * inst.world * glm::vec4(mesh.vertices[idx].position, 1.0f);
            // GL-style NDC has y up; the image's row 0 is the top.
            tri_px.push_back({(c.x / c.w * 0.5f + 0.5f) * w, (0.5f - c.y / c.w * 0.5f) * h});
        }
    }
    auto edge = [](glm::vec2 a, glm::vec2 b, glm::vec2 p) {
        return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
    };
    size_t covered = 0;
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const glm::vec2 p{x + 0.5f, y + 0.5f};
            for (size_t t = 0; t + 2 < tri_px.size(); t += 3) {
                const float e0 = edge(tri_px[t], tri_px[t + 1], p);
                const float e1 = edge(tri_px[t + 1], tri_px[t + 2], p);
                const float e2 = edge(tri_px[t + 2], tri_px[t], p);
                if ((e0 >= 0 && e1 >= 0 && e2 >= 0) || (e0 <= 0 && e1 <= 0 && e2 <= 0)) {
                    ++covered;
                    break;
                }
            }
        }
    return covered;
}

uint32_t pixel(const FrameResult& f, uint32_t x, uint32_t y) {
    const uint8_t* p = &f.rgba8[(size_t(y) * f.width + x) * 4];
    return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

size_t non_sky_pixels(const FrameResult& f, uint32_t sky) {
    size_t n = 0;
    for (uint32_t y = 0; y < f.height; ++y)
        for (uint32_t x = 0; x < f.width; ++x) n += pixel(f, x, y) != sky;
    return n;
}

// `background`: the clear colour of a frame rendered with sky=off.
void check_frame(const FrameResult& f, const scene::Scene& s, uint32_t background) {
    ASSERT_EQ(f.rgba8.size(), size_t(f.width) * f.height * 4);
    const size_t expected = expected_coverage(s, f.width, f.height);
    // Edge pixels may go either way between the two rasterizers: allow 2% of the image.
    const double tolerance = 0.02 * f.width * f.height;
    ASSERT_TRUE(f.covered_pixels);
    EXPECT_NEAR(double(*f.covered_pixels), double(expected), tolerance)
        << f.width << "x" << f.height;
    EXPECT_NEAR(double(non_sky_pixels(f, background)), double(expected), tolerance);
    EXPECT_GT(expected, size_t(f.width) * f.height / 5);       // the scene fills a good part
    EXPECT_LT(expected, size_t(f.width) * f.height * 9 / 10);  // and sky remains
}

Settings sky_off() {
    Settings s;
    s.set("sky", "off");
    return s;
}

TEST(RendererSmoke, GroundAndCube) {
    const scene::Scene s = smoke_scene();
    RendererOptions options;
    options.validate = true;
    Renderer renderer(options);
    renderer.set_scene(s);
    const Settings settings = sky_off();  // a uniform background: coverage by colour

    const FrameResult a = renderer.render(s.camera, settings, {.width = 128, .height = 96});
    ASSERT_EQ(a.width, 128u);
    ASSERT_EQ(a.height, 96u);
    std::printf("smoke 128x96: gpu %.3f ms, cpu %.3f ms\n", a.gpu_ms, a.cpu_ms);

    // Top-left is background: opaque and blue-ish (forward's clear colour, tonemapped).
    const uint32_t sky = pixel(a, 0, 0);
    const uint8_t* sp = &a.rgba8[0];
    EXPECT_EQ(sp[3], 255);
    EXPECT_GT(sp[2], sp[0]);
    check_frame(a, s, sky);

    std::set<uint32_t> colours;
    for (uint32_t y = 0; y < a.height; ++y)
        for (uint32_t x = 0; x < a.width; ++x) colours.insert(pixel(a, x, y));
    EXPECT_GT(colours.size(), 50u) << "a lit, textured scene has many distinct colours";
    EXPECT_GT(a.gpu_ms, 0.0);

    // The default frame (procedural sky): the same coverage, a sky that is blue at the top.
    const FrameResult with_sky =
        renderer.render(s.camera, Settings{}, {.width = 128, .height = 96});
    stbi_write_png("/tmp/ds_smoke.png", int(with_sky.width), int(with_sky.height), 4,
                   with_sky.rgba8.data(), int(with_sky.width * 4));
    EXPECT_EQ(with_sky.covered_pixels, a.covered_pixels);
    EXPECT_GT(with_sky.rgba8[2], with_sky.rgba8[0]);

    const FrameResult b = renderer.render(s.camera, settings, {.width = 128, .height = 96});
    EXPECT_TRUE(a.rgba8 == b.rgba8) << "same input must give byte-identical pixels";

    const FrameResult big = renderer.render(s.camera, settings, {.width = 200, .height = 150});
    EXPECT_EQ(big.rgba8.size(), size_t(200) * 150 * 4);
    check_frame(big, s, sky);
    std::printf("smoke 200x150: gpu %.3f ms, cpu %.3f ms\n", big.gpu_ms, big.cpu_ms);

    const FrameResult again = renderer.render(s.camera, settings, {.width = 128, .height = 96});
    EXPECT_TRUE(a.rgba8 == again.rgba8) << "resizing back must not change the image";

    // A second scene replaces the first; an empty scene draws only background.
    renderer.set_scene(scene::Scene{});
    const FrameResult empty = renderer.render(s.camera, settings, {.width = 32, .height = 24});
    EXPECT_EQ(empty.covered_pixels, 0u);
    for (uint32_t y = 0; y < empty.height; ++y)
        for (uint32_t x = 0; x < empty.width; ++x) ASSERT_EQ(pixel(empty, x, y), sky);
    EXPECT_THROW(renderer.render(s.camera, settings, {.width = 0, .height = 24}), ds::Error);

    EXPECT_EQ(renderer.validation_message_count(), 0u);
}

// Quad in the XY plane at depth z facing +Z, from (x0,y0) to (x1,y1), uv 0..1 left to right.
scene::Mesh quad_mesh(glm::vec2 lo, glm::vec2 hi, float z, uint32_t material) {
    scene::Mesh m;
    m.name = "quad";
    m.material = material;
    const glm::vec3 n{0, 0, 1};
    const glm::vec4 t{1, 0, 0, 1};
    m.vertices = {{{lo.x, lo.y, z}, n, {0, 1}, t},
                  {{hi.x, lo.y, z}, n, {1, 1}, t},
                  {{hi.x, hi.y, z}, n, {1, 0}, t},
                  {{lo.x, hi.y, z}, n, {0, 0}, t}};
    m.indices = {0, 1, 2, 0, 2, 3};
    for (const auto& v : m.vertices) m.bounds.extend(v.position);
    return m;
}

// Mask quad (left), two overlapping blend quads (right, red in front of green), on sky.
scene::Scene alpha_scene() {
    scene::Scene s;
    scene::Material mask;
    mask.name = "mask";
    mask.alpha_mode = scene::AlphaMode::Mask;
    mask.double_sided = true;
    mask.metallic_factor = 0.0f;
    mask.base_color.texture = 0;
    scene::Material red;
    red.name = "red glass";
    red.alpha_mode = scene::AlphaMode::Blend;
    red.base_color_factor = {1.0f, 0.0f, 0.0f, 0.5f};
    red.metallic_factor = 0.0f;
    scene::Material green = red;
    green.name = "green glass";
    green.base_color_factor = {0.0f, 1.0f, 0.0f, 0.5f};
    s.materials = {mask, red, green};
    // 2x1 texels, nearest: the left half is opaque, the right half is cut out.
    scene::Image cutout;
    cutout.name = "cutout";
    cutout.width = 2;
    cutout.height = 1;
    cutout.srgb = true;
    cutout.rgba8 = {255, 255, 255, 255, 255, 255, 255, 0};
    s.images = {cutout};
    scene::Sampler nearest;
    nearest.mag = nearest.min = nearest.mip = scene::Filter::Nearest;
    nearest.wrap_s = nearest.wrap_t = scene::Wrap::ClampToEdge;
    s.samplers = {nearest, scene::Sampler{}};
    s.textures = {scene::Texture{0, 0}};
    s.meshes = {quad_mesh({-2.0f, -1.0f}, {-0.5f, 1.0f}, 0.0f, 0),
                quad_mesh({0.5f, -1.0f}, {2.0f, 1.0f}, 0.5f, 1),    // red, nearer
                quad_mesh({1.0f, -0.5f}, {2.5f, 1.5f}, -0.5f, 2)};  // green, farther
    // Authored near-to-far, so drawing in authored order would composite wrongly.
    s.instances = {{0, glm::mat4(1.0f), "a"}, {1, glm::mat4(1.0f), "b"}, {2, glm::mat4(1.0f), "c"}};
    s.draw_groups = {{0, scene::AlphaMode::Mask, true, 0, 1},
                     {1, scene::AlphaMode::Blend, false, 1, 1},
                     {2, scene::AlphaMode::Blend, false, 2, 1}};
    s.camera.position = {0.0f, 0.0f, 6.0f};
    s.camera.forward = {0.0f, 0.0f, -1.0f};
    s.camera.up = {0.0f, 1.0f, 0.0f};
    return s;
}

glm::ivec2 project(const scene::Scene& s, uint32_t w, uint32_t h, glm::vec3 p) {
    const glm::mat4 vp =
        glm::perspective(s.camera.yfov, float(w) / float(h), s.camera.znear, s.camera.zfar) *
        s.camera.view();
    const glm::vec4 c = vp * glm::vec4(p, 1.0f);
    return {int((c.x / c.w * 0.5f + 0.5f) * w), int((0.5f - c.y / c.w * 0.5f) * h)};
}

TEST(RendererSmoke, MaskAndBlend) {
    const scene::Scene s = alpha_scene();
    RendererOptions options;
    options.validate = true;
    Renderer renderer(options);
    renderer.set_scene(s);
    const FrameResult f = renderer.render(s.camera, sky_off(), {.width = 160, .height = 120});
    const uint32_t sky = pixel(f, 0, 0);
    auto at = [&](glm::vec3 p) {
        const glm::ivec2 q = project(s, f.width, f.height, p);
        return pixel(f, uint32_t(q.x), uint32_t(q.y));
    };
    auto channel = [](uint32_t rgba, int c) { return int((rgba >> (8 * c)) & 0xff); };

    EXPECT_NE(at({-1.6f, 0.0f, 0.0f}), sky) << "opaque half of the MASK quad is drawn";
    EXPECT_EQ(at({-0.9f, 0.0f, 0.0f}), sky) << "alpha 0 half of the MASK quad is discarded";

    const uint32_t red_only = at({0.75f, 0.0f, 0.5f});
    EXPECT_GT(channel(red_only, 0), channel(sky, 0)) << "red glass tints the sky red";
    EXPECT_LT(channel(red_only, 2), channel(sky, 2));
    EXPECT_EQ(channel(red_only, 3), 255) << "the final image is opaque";
    // Where red (near) covers green (far): back-to-front gives red the last word.
    const uint32_t both = at({1.6f, 0.2f, 0.5f});
    EXPECT_GT(channel(both, 0), channel(both, 1)) << "blend order must be back to front";

    const FrameResult again = renderer.render(s.camera, sky_off(), {.width = 160, .height = 120});
    EXPECT_TRUE(f.rgba8 == again.rgba8);
    stbi_write_png("/tmp/ds_smoke_alpha.png", int(f.width), int(f.height), 4, f.rgba8.data(),
                   int(f.width * 4));
    EXPECT_EQ(renderer.validation_message_count(), 0u);
}

}  // namespace
