// ao_spatial and ao_temporal, fed a known input in place of the previous pass's output (packed
// as gtao writes it: AO, view distance, view normal), so every expected value follows from the
// geometry and the filters' definitions.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tests/gpu/screen_space/screen_space_test.h"

namespace ds::test {
namespace {

constexpr uint32_t kFilterWidth = 240, kFilterHeight = 160;

// AO per surface: the wall 0.2, everything else 1 (what a perfect GTAO would not produce, but
// what makes bleeding across the wall's edges measurable).
float wall_dark(const PixelHit& h) {
    return h.surface == Surface::Box ? 0.2f : 1.0f;
}

std::vector<float> raw_values(const SyntheticFrame& frame, uint32_t w, uint32_t h,
                              const std::function<float(const PixelHit&, glm::ivec2)>& value) {
    std::vector<float> out(size_t(w) * h);
    const glm::ivec2 full{int(frame.width), int(frame.height)};
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const glm::ivec2 s = ao_source_pixel({int(x), int(y)}, {int(w), int(h)}, full);
            out[size_t(y) * w + x] =
                value(frame.hit(uint32_t(s.x), uint32_t(s.y)), {int(x), int(y)});
        }
    return out;
}

// Runs ao_spatial on `raw` (imported as ao_raw), then ao_temporal (no history: its output is
// the upsampled current value); returns ao_filtered (at raw's size) and ao (full size).
FrameOutput run_spatial(GpuRig& rig, const vk::Image& raw) {
    passes::AoSpatialPass spatial(rig.services());
    passes::AoTemporalPass temporal(rig.services());
    graph::RenderGraph graph(rig.context());
    return rig.run_frame(
        graph,
        [&](graph::RenderGraph& g, const passes::FrameInputs& in, passes::FrameResources& res) {
            res.ao_raw = rig.import_input(g, "ao_raw", raw);
            spatial.add(g, in, res);
            temporal.add(g, in, res);
        },
        {"ao_filtered", "ao"});
}

class AoSpatial : public ScreenSpaceTest, public ::testing::WithParamInterface<float> {};

// No AO crosses the wall's silhouette (floor far behind its top edge) nor the corner (floor
// against the wall's face), neither in the filter nor in ao_temporal's upsampling: a plain 5x5
// blur would mix 0.2 and 1 in a 2-pixel band, a plain bilinear upsampling in a 1-pixel one.
TEST_P(AoSpatial, KeepsDepthAndNormalEdges) {
    const float scale = GetParam();
    const SyntheticFrame frame =
        render_synthetic(corner_scene(), corner_camera(), kFilterWidth, kFilterHeight, true);
    rig().upload(frame);
    const uint32_t w = uint32_t(float(kFilterWidth) * scale),
                   h = uint32_t(float(kFilterHeight) * scale);
    const vk::Image raw = rig().make_packed_ao(
        frame, w, h,
        raw_values(frame, w, h, [](const PixelHit& hit, glm::ivec2) { return wall_dark(hit); }));
    const HostImage out = run_spatial(rig(), raw).images.at("ao");
    write_png(png_path(std::string("spatial_edges_") + (scale < 1.0f ? "half" : "full")), out);

    size_t floor_next_to_wall = 0;
    for (uint32_t y = 0; y < kFilterHeight; ++y)
        for (uint32_t x = 0; x < kFilterWidth; ++x) {
            const PixelHit& hit = frame.hit(x, y);
            if (hit.surface == Surface::Sky) continue;
            const float expected = wall_dark(hit);
            ASSERT_NEAR(out.at(x, y), expected, 0.01f) << x << "," << y;
            if (hit.surface == Surface::Floor &&
                !neighbourhood_is(frame, {int(x), int(y)}, 2, Surface::Floor))
                ++floor_next_to_wall;
        }
    EXPECT_GT(floor_next_to_wall, 100u);  // the edges were really inside the kernel
}

INSTANTIATE_TEST_SUITE_P(Resolutions, AoSpatial, ::testing::Values(1.0f, 0.5f),
                         [](const auto& info) { return info.param < 1.0f ? "half" : "full"; });

// GTAO's 4x4 rotation pattern averages out exactly on a plane: the 1 2 2 2 1 tent weighs
// every residue mod 4 alike.
TEST_F(AoSpatial, RemovesTheFourByFourPattern) {
    const SyntheticFrame frame =
        render_synthetic(corner_scene(), corner_camera(), kFilterWidth, kFilterHeight, true);
    rig().upload(frame);
    static const int kBayer[16] = {0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5};
    const vk::Image raw = rig().make_packed_ao(
        frame, kFilterWidth, kFilterHeight,
        raw_values(frame, kFilterWidth, kFilterHeight, [](const PixelHit&, glm::ivec2 q) {
            return float(kBayer[(q.y & 3) * 4 + (q.x & 3)]) / 15.0f;
        }));
    const HostImage out = run_spatial(rig(), raw).images.at("ao_filtered");
    size_t checked = 0;
    for (uint32_t y = 0; y < kFilterHeight; ++y)
        for (uint32_t x = 0; x < kFilterWidth; ++x)
            if (neighbourhood_is(frame, {int(x), int(y)}, 2, Surface::Floor)) {
                ASSERT_NEAR(out.at(x, y), 0.5f, 0.012f) << x << "," << y;
                ++checked;
            }
    EXPECT_GT(checked, 10000u);
}

// ao_temporal alone: ao_filtered comes from `value` per pixel of the current frame.
struct TemporalRun {
    passes::AoTemporalPass pass;
    graph::RenderGraph graph;
    explicit TemporalRun(GpuRig& rig) : pass(rig.services()), graph(rig.context()) {}

    FrameOutput frame(GpuRig& rig, const SyntheticFrame& f,
                      const std::function<float(const PixelHit&)>& value) {
        std::vector<float> current(size_t(f.width) * f.height);
        for (size_t i = 0; i < current.size(); ++i) current[i] = value(f.hits[i]);
        const vk::Image image = rig.make_packed_ao(f, f.width, f.height, current);
        return rig.run_frame(
            graph,
            [&](graph::RenderGraph& g, const passes::FrameInputs& in, passes::FrameResources& res) {
                res.ao_filtered = rig.import_input(g, "ao_filtered", image);
                pass.add(g, in, res);
            },
            {"ao", "ao_history.current"});
    }
};

using AoTemporal = ScreenSpaceTest;

float constant(float v, const PixelHit& h) {
    return h.surface == Surface::Sky ? 1.0f : v;
}

TEST_F(AoTemporal, InvalidHistoryOutputsCurrentThenBlendsAndConverges) {
    const SyntheticFrame frame =
        render_synthetic(corner_scene(), corner_camera(), kFilterWidth, kFilterHeight, true);
    rig().upload(frame);
    TemporalRun run(rig());
    const auto surfaces =
        select_pixels(frame, [](const PixelHit& h) { return h.surface != Surface::Sky; });

    // First frame: no history, output = current exactly; the history stores it with the
    // view distance.
    FrameOutput out = run.frame(rig(), frame, [](const PixelHit& h) { return constant(0.2f, h); });
    EXPECT_FALSE(run.pass.last_history_valid());
    const glm::mat4 view = frame.uniforms.view;
    for (glm::ivec2 p : surfaces) {
        ASSERT_NEAR(out.images.at("ao").at(p.x, p.y), 0.2f, 0.5f / 255.0f);
        const float distance = -(view * glm::vec4(frame.hit(p.x, p.y).position, 1.0f)).z;
        ASSERT_NEAR(out.images.at("ao_history.current").g_at(p.x, p.y), distance,
                    0.002f * distance);
    }

    // Then the current value jumps to 1 under a static camera: out_k = 1 - 0.8 * 0.9^(k-1).
    float expected = 0.2f;
    for (int k = 2; k <= 25; ++k) {
        out = run.frame(rig(), frame, [](const PixelHit& h) { return constant(1.0f, h); });
        EXPECT_TRUE(run.pass.last_history_valid());
        expected = 0.9f * expected + 0.1f;
        float worst = 0.0f;
        for (glm::ivec2 p : surfaces)
            worst = std::max(worst, std::abs(out.images.at("ao").at(p.x, p.y) - expected));
        ASSERT_LT(worst, 0.01f) << "frame " << k << " expected " << expected;
    }

    // A camera cut: the graph drops the history and the output is the current value again.
    run.graph.invalidate_history();
    out = run.frame(rig(), frame, [](const PixelHit& h) { return constant(0.4f, h); });
    EXPECT_FALSE(run.pass.last_history_valid());
    for (glm::ivec2 p : surfaces)
        ASSERT_NEAR(out.images.at("ao").at(p.x, p.y), 0.4f, 0.5f / 255.0f);
}

// The wall disappears between two frames (static camera): where it stood, the history saw a
// nearer surface and is dropped; elsewhere it blends. (Where the floor behind the wall lies
// within the tolerance of the wall's distance, near its foot, the history is kept: a depth
// test cannot tell such surfaces apart, and their AO is alike there anyway.)
TEST_F(AoTemporal, DropsHistoryOfAnotherSurface) {
    const SyntheticFrame with_wall =
        render_synthetic(corner_scene(), corner_camera(), kFilterWidth, kFilterHeight, true);
    SyntheticScene empty = corner_scene();
    empty.boxes.clear();
    const SyntheticFrame without_wall =
        render_synthetic(empty, corner_camera(), kFilterWidth, kFilterHeight, true);
    TemporalRun run(rig());
    rig().upload(with_wall);
    run.frame(rig(), with_wall, [](const PixelHit& h) { return constant(0.2f, h); });
    rig().upload(without_wall);
    const HostImage ao =
        run.frame(rig(), without_wall, [](const PixelHit& h) { return constant(1.0f, h); })
            .images.at("ao");
    size_t revealed = 0, kept = 0;
    for (uint32_t y = 1; y + 1 < kFilterHeight; ++y)
        for (uint32_t x = 1; x + 1 < kFilterWidth; ++x) {
            const glm::ivec2 p{int(x), int(y)};
            if (!neighbourhood_is(without_wall, p, 1, Surface::Floor)) continue;
            const glm::mat4& view = with_wall.uniforms.view;
            const float before = -(view * glm::vec4(with_wall.hit(x, y).position, 1.0f)).z;
            const float after = -(view * glm::vec4(without_wall.hit(x, y).position, 1.0f)).z;
            const float tolerance = passes::AoTemporalPass::Params{}.depth_tolerance;
            if (neighbourhood_is(with_wall, p, 1, Surface::Box) &&
                after - before > 2.0f * tolerance * after) {
                ASSERT_NEAR(ao.at(x, y), 1.0f, 0.5f / 255.0f) << x << "," << y;
                ++revealed;
            } else if (neighbourhood_is(with_wall, p, 1, Surface::Floor)) {
                ASSERT_NEAR(ao.at(x, y), 0.28f, 0.01f) << x << "," << y;
                ++kept;
            }
        }
    EXPECT_GT(revealed, 1000u);
    EXPECT_GT(kept, 1000u);
}

// A moving camera: the history is fetched where the surface point was last frame. The AO is
// painted on the floor in 1 m stripes along x, so fetching at the pixel's own position (no
// reprojection) would blend the wrong stripe near every stripe edge.
TEST_F(AoTemporal, ReprojectsWithThePreviousViewProjection) {
    const auto stripes = [](const PixelHit& h) {
        if (h.surface != Surface::Floor) return constant(0.5f, h);
        return std::fmod(h.position.x + 100.0f, 1.0f) < 0.5f ? 0.2f : 0.8f;
    };
    SyntheticCamera camera = corner_camera();
    const SyntheticFrame first =
        render_synthetic(corner_scene(), camera, kFilterWidth, kFilterHeight, true);
    camera.eye += glm::vec3(0.3f, 0.0f, -0.4f);
    camera.target += glm::vec3(0.3f, 0.0f, -0.4f);
    SyntheticFrame second =
        render_synthetic(corner_scene(), camera, kFilterWidth, kFilterHeight, true);
    second.uniforms.previous_view_projection = first.uniforms.view_projection;

    TemporalRun run(rig());
    rig().upload(first);
    run.frame(rig(), first, stripes);
    rig().upload(second);
    const HostImage ao = run.frame(rig(), second, stripes).images.at("ao");
    write_png(png_path("temporal_stripes"), ao);

    size_t checked = 0, moved_across_stripe = 0;
    for (uint32_t y = 0; y < kFilterHeight; ++y)
        for (uint32_t x = 0; x < kFilterWidth; ++x) {
            const PixelHit& hit = second.hit(x, y);
            if (!neighbourhood_is(second, {int(x), int(y)}, 1, Surface::Floor)) continue;
            // Last frame's pixel of this point: on the floor too, and 5 cm inside a stripe.
            // Its whole bilinear footprint there shows the same stripe.
            const auto before = first.pixel_of(hit.position);
            if (!before || !neighbourhood_is(first, *before, 1, Surface::Floor)) continue;
            bool same_stripe = true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    same_stripe &= stripes(first.hit(uint32_t(before->x + dx),
                                                     uint32_t(before->y + dy))) == stripes(hit);
            if (!same_stripe) continue;
            ASSERT_NEAR(ao.at(x, y), stripes(hit), 0.01f) << x << "," << y;
            ++checked;
            if (std::abs(stripes(first.hit(x, y)) - stripes(hit)) > 0.1f) ++moved_across_stripe;
        }
    EXPECT_GT(checked, 5000u);
    EXPECT_GT(moved_across_stripe, 1000u);  // without reprojection these would be wrong
}

}  // namespace
}  // namespace ds::test
