// GTAO (through ao_spatial and ao_temporal, as forward sees it) on a synthetic corner: a floor
// meeting a wall at a right angle, in both depth conventions and both GTAO resolutions.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <ostream>

#include "renderer/shader/compiler.h"
#include "tests/gpu/screen_space/screen_space_test.h"

namespace ds::test {
namespace {

constexpr uint32_t kGtaoWidth = 480, kGtaoHeight = 320;
const glm::vec3 kGtaoSun{1.0f, 0.6f, 0.2f};  // towards +X: the wall shades the floor in front
constexpr int kBorder = 48;  // pixels: about the AO radius's projection at the corner

struct Variant {
    bool reverse_z;
    float gtao_scale;
};

std::string variant_name(const Variant& v) {
    return std::string(v.reverse_z ? "reverse_z" : "forward_z") +
           (v.gtao_scale < 1.0f ? "_half" : "_full");
}

void PrintTo(const Variant& v, std::ostream* os) {
    *os << variant_name(v);
}

class GtaoCorner : public ScreenSpaceTest, public ::testing::WithParamInterface<Variant> {};

TEST_P(GtaoCorner, OpenFloorIsUnoccludedCornerIsDarkSkyIsOne) {
    const Variant v = GetParam();
    const SyntheticFrame frame = render_synthetic(corner_scene(), corner_camera(), kGtaoWidth,
                                                  kGtaoHeight, v.reverse_z, kGtaoSun);
    rig().upload(frame);
    ScreenSpacePasses passes(rig().services(), v.gtao_scale);
    graph::RenderGraph graph(rig().context());
    const FrameOutput out = rig().run_frame(graph, passes.declare(),
                                            {"ao_raw", "ao_filtered", "ao", "contact_shadows"});
    const HostImage& ao = out.images.at("ao");
    for (const auto& [name, image] : out.images)
        write_png(png_path(name + "_" + variant_name(v)), image);
    EXPECT_EQ(out.images.at("ao_raw").width, uint32_t(float(kGtaoWidth) * v.gtao_scale));

    // Open floor: farther from the wall than the 1 m radius (plus the filter's reach).
    const auto open_floor = select_pixels(frame, [](const PixelHit& h) {
        const glm::vec3 p = h.position;
        const float dx = p.x < 0.0f ? -p.x : std::max(0.0f, p.x - kWallThickness);
        const float dz = std::max(0.0f, std::abs(p.z) - kWallHalfLength);
        return h.surface == Surface::Floor && std::hypot(dx, dz) > 1.3f;
    });
    ASSERT_GT(open_floor.size(), 1000u);
    float open_min = 1.0f;
    for (glm::ivec2 p : open_floor) open_min = std::min(open_min, ao.at(p.x, p.y));
    EXPECT_GE(open_min, 0.95f);

    // Floor in the corner, 2 to 10 cm from the wall's foot: about half the hemisphere is wall.
    // Not near the image border: occluders off screen are unknown to a screen-space method.
    std::vector<glm::ivec2> corner;
    for (glm::ivec2 p : select_pixels(frame, [](const PixelHit& h) {
             return h.surface == Surface::Floor && h.position.x > -0.1f && h.position.x < -0.02f &&
                    std::abs(h.position.z) < 3.0f;
         }))
        if (p.x >= kBorder && p.y >= kBorder && p.x < int(kGtaoWidth) - kBorder &&
            p.y < int(kGtaoHeight) - kBorder)
            corner.push_back(p);
    ASSERT_GT(corner.size(), 20u);
    float corner_max = 0.0f, corner_sum = 0.0f;
    for (glm::ivec2 p : corner) {
        corner_max = std::max(corner_max, ao.at(p.x, p.y));
        corner_sum += ao.at(p.x, p.y);
    }
    EXPECT_LE(corner_max, 0.8f);
    std::printf("corner AO: mean %.3f max %.3f; open floor min %.3f\n",
                corner_sum / float(corner.size()), corner_max, open_min);

    const auto sky =
        select_pixels(frame, [](const PixelHit& h) { return h.surface == Surface::Sky; });
    ASSERT_GT(sky.size(), 100u);
    for (glm::ivec2 p : sky) ASSERT_EQ(ao.at(p.x, p.y), 1.0f) << p.x << "," << p.y;
}

INSTANTIATE_TEST_SUITE_P(Variants, GtaoCorner,
                         ::testing::Values(Variant{true, 0.5f}, Variant{true, 1.0f},
                                           Variant{false, 0.5f}, Variant{false, 1.0f}),
                         [](const auto& info) { return variant_name(info.param); });

using Gtao = ScreenSpaceTest;

// The whole chain under a static camera: the first frame has no history (ao is the upsampled
// ao_filtered alone); later frames blend a history equal to the current value, so nothing
// drifts, not even by one 8-bit step (ao_temporal quantises the current value first).
TEST_F(Gtao, StaticCameraStaysStable) {
    rig().upload(render_synthetic(corner_scene(), corner_camera(), 240, 160, true, kGtaoSun));
    ScreenSpacePasses passes(rig().services());
    graph::RenderGraph graph(rig().context());
    std::vector<float> first;
    for (int frame = 0; frame < 4; ++frame) {
        const HostImage ao = rig().run_frame(graph, passes.declare(), {"ao"}).images.at("ao");
        EXPECT_EQ(passes.temporal.last_history_valid(), frame > 0);
        if (frame == 0)
            first = ao.r;
        else
            EXPECT_EQ(ao.r, first) << "frame " << frame;
    }
}

// The AO forward reads, as built (half resolution, kSlices x kSteps, filtered at half
// resolution and upsampled in ao_temporal), against a high-quality setting of the same
// shaders (full resolution, 8 slices x 16 steps): the cheap path must not drift beyond the
// tolerance docs/history/issue-14.md states (issue 14: mean |dAO| <= 0.02, 99th percentile <= 0.1).
TEST_F(Gtao, DefaultsStayWithinToleranceOfHighQuality) {
    const SyntheticFrame frame =
        render_synthetic(corner_scene(), corner_camera(), kGtaoWidth, kGtaoHeight, true, kGtaoSun);
    rig().upload(frame);
    const auto ao_of = [&](ScreenSpacePasses& passes) {
        graph::RenderGraph graph(rig().context());
        return rig().run_frame(graph, passes.declare(), {"ao"}).images.at("ao");
    };
    ScreenSpacePasses defaults(rig().services());
    ScreenSpacePasses reference(rig().services(), 1.0f, 8, 16);
    const HostImage a = ao_of(defaults), b = ao_of(reference);
    write_png(png_path("ao_defaults"), a);
    write_png(png_path("ao_high_quality"), b);
    std::vector<float> diff;
    double sum = 0.0;
    for (glm::ivec2 p :
         select_pixels(frame, [](const PixelHit& h) { return h.surface != Surface::Sky; })) {
        diff.push_back(std::abs(a.at(p.x, p.y) - b.at(p.x, p.y)));
        sum += diff.back();
    }
    ASSERT_GT(diff.size(), 10000u);
    std::sort(diff.begin(), diff.end());
    const double mean = sum / double(diff.size());
    const float p99 = diff[diff.size() * 99 / 100];
    std::printf("defaults vs high quality: mean |dAO| %.4f, p99 %.4f, max %.4f\n", mean, p99,
                diff.back());
    EXPECT_LE(mean, 0.02);
    EXPECT_LE(p99, 0.1f);
}

TEST_F(Gtao, SameInputSameOutput) {
    rig().upload(
        render_synthetic(corner_scene(), corner_camera(), kGtaoWidth, kGtaoHeight, true, kGtaoSun));
    passes::GtaoPass gtao(rig().services());
    graph::RenderGraph graph(rig().context());
    auto declare = [&](graph::RenderGraph& g, const passes::FrameInputs& in,
                       passes::FrameResources& res) { gtao.add(g, in, res); };
    const HostImage a = rig().run_frame(graph, declare, {"ao_raw"}).images.at("ao_raw");
    const HostImage b = rig().run_frame(graph, declare, {"ao_raw"}).images.at("ao_raw");
    EXPECT_EQ(a.r, b.r);
}

TEST_F(Gtao, SwitchedOffAddsNothing) {
    rig().upload(render_synthetic(corner_scene(), corner_camera(), 64, 48, true, kGtaoSun));
    ScreenSpacePasses passes(rig().services());
    graph::RenderGraph graph(rig().context());
    passes::FrameOptions options;
    options.gtao = false;
    options.contact_shadows = false;
    passes::FrameResources seen;
    rig().run_frame(
        graph,
        [&](graph::RenderGraph& g, const passes::FrameInputs& in, passes::FrameResources& res) {
            passes.declare()(g, in, res);
            seen = res;
        },
        {}, options);
    EXPECT_TRUE(graph.passes().empty());
    EXPECT_FALSE(seen.ao_raw.valid());
    EXPECT_FALSE(seen.ao_filtered.valid());
    EXPECT_FALSE(seen.ao.valid());
    EXPECT_FALSE(seen.contact_shadows.valid());
}

// Hot reload: a broken shader throws and the pass keeps drawing with its last pipeline.
TEST_F(Gtao, FailedRebuildKeepsThePipeline) {
    namespace fs = std::filesystem;
    const fs::path root = fs::temp_directory_path() / "depthscope_ss_shaders";
    fs::remove_all(root);
    fs::copy(shader::Compiler::default_shader_root(), root, fs::copy_options::recursive);
    shader::Compiler compiler(root, {});
    passes::PassServices services = rig().services();
    passes::PassServices local{services.context,
                               compiler,
                               services.frame_layout,
                               services.material_layout,
                               services.preferred_depth_format,
                               services.readback};
    passes::GtaoPass gtao(local);

    rig().upload(render_synthetic(corner_scene(), corner_camera(), 64, 48, true, kGtaoSun));
    graph::RenderGraph graph(rig().context());
    auto declare = [&](graph::RenderGraph& g, const passes::FrameInputs& in,
                       passes::FrameResources& res) { gtao.add(g, in, res); };
    const HostImage before = rig().run_frame(graph, declare, {"ao_raw"}).images.at("ao_raw");

    std::ofstream(root / passes::GtaoPass::kShader, std::ios::app) << "\nthis is not GLSL\n";
    vk::DestroyList retired;
    EXPECT_THROW(gtao.rebuild_pipelines(retired), shader::ShaderError);
    EXPECT_EQ(retired.size(), 0u);
    const HostImage after = rig().run_frame(graph, declare, {"ao_raw"}).images.at("ao_raw");
    EXPECT_EQ(before.r, after.r);
    fs::remove_all(root);
}

// GPU time of each pass at 1280x720, printed: a benchmark, not a test, so out of the suite
// (build/tests/gpu/screen_space/screen_space_tests --gtest_also_run_disabled_tests
// --gtest_filter='*Timing*' runs it).
TEST_F(Gtao, DISABLED_TimingAt1280x720) {
    const SyntheticFrame frame =
        render_synthetic(corner_scene(), corner_camera(), 1280, 720, true, kGtaoSun);
    rig().upload(frame);
    for (float scale : {0.5f, 1.0f}) {
        ScreenSpacePasses passes(rig().services(), scale);
        graph::RenderGraph graph(rig().context());
        FrameOutput out;
        for (int i = 0; i < 3; ++i) out = rig().run_frame(graph, passes.declare(), {"ao"});
        write_png(png_path(scale < 1.0f ? "ao_1280x720_half" : "ao_1280x720_full"),
                  out.images.at("ao"));
        for (const graph::PassResult& r : out.passes)
            std::printf("gtao scale %.1f | %-16s %8.3f ms\n", scale, r.name.c_str(), r.gpu_ms);
    }
}

}  // namespace
}  // namespace ds::test
