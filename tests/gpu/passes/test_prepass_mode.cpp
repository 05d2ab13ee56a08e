// prepass_mode (issue 14) through the Renderer facade with validation on (the fixture fails any
// test that leaves a validation message): the Z-only prepass's passes, pipelines and
// resources, its image against the G-buffer prepass's, and every diagnostic in depth mode.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "renderer/common/error.h"
#include "renderer/passes/depth_prepass.h"
#include "renderer/passes/draw_counts.h"
#include "renderer/passes/equal_check.h"
#include "renderer/passes/pixel_history.h"
#include "renderer/passes/zfight.h"
#include "renderer/renderer.h"
#include "renderer/scene/loader.h"
#include "renderer/vk/capabilities.h"
#include "tests/gpu/passes/shared_renderer.h"

namespace {

using namespace ds;
using test::differing_pixels;
using test::names;

constexpr uint32_t kModeWidth = 320, kModeHeight = 180;

class PrepassMode : public test::SceneSwitching {
  protected:
    FrameResult frame(const std::string& scene, std::vector<std::string> settings,
                      const std::string& inspect = "", uint32_t w = kModeWidth,
                      uint32_t h = kModeHeight) {
        return render(scene, settings, w, h, ReadBack::Yes, {inspect});
    }
    // The same frame in both modes: [0] gbuffer, [1] depth.
    std::array<FrameResult, 2> both(const std::string& scene, std::vector<std::string> settings,
                                    const std::string& inspect = "", uint32_t w = kModeWidth,
                                    uint32_t h = kModeHeight) {
        std::vector<std::string> g = settings, d = settings;
        g.push_back("prepass_mode=gbuffer");
        d.push_back("prepass_mode=depth");
        return {frame(scene, g, inspect, w, h), frame(scene, d, inspect, w, h)};
    }
    bool has_msaa4() const {
        const vk::DeviceReport& r = renderer_->device_report();
        return (r.color_sample_counts & r.depth_sample_counts & VK_SAMPLE_COUNT_4_BIT) != 0;
    }
};

const PassResult& pass(const FrameResult& f, const std::string& name) {
    for (const PassResult& p : f.passes)
        if (p.name == name) return p;
    static const PassResult none;
    ADD_FAILURE() << "no pass " << name;
    return none;
}

bool has_resource(const FrameResult& f, const std::string& name) {
    return std::any_of(f.resources.begin(), f.resources.end(),
                       [&](const ResourceSummary& r) { return r.name == name; });
}

const PipelineReport* pipeline(const PassResult& p, const std::string& name) {
    for (const PipelineReport& r : p.pipelines)
        if (r.name == name) return &r;
    ADD_FAILURE() << p.name << " has no pipeline " << name;
    return nullptr;
}

double percent(size_t n, const FrameResult& f) {
    return 100.0 * double(n) / double(size_t(f.width) * f.height);
}

TEST_F(PrepassMode, KnobIsValidatedAndDefaultsToGbuffer) {
    EXPECT_EQ(Settings().get("prepass_mode"), "gbuffer");
    EXPECT_EQ(test::settings_of({"prepass_mode=depth"}).get("prepass_mode"), "depth");
    for (const char* bad : {"prepass_mode=zonly", "prepass_mode=", "prepass_mode=Depth"}) {
        try {
            test::settings_of({bad});
            ADD_FAILURE() << bad << " was accepted";
        } catch (const UsageError& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find("prepass_mode"), std::string::npos) << what;
            EXPECT_NE(what.find("gbuffer|depth"), std::string::npos) << what;
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        }
    }
}

// Depth mode: the same seed frame, plus normals_from_depth for GTAO and contact shadows; the
// prepass has no colour target, its opaque pipeline no fragment stage.
TEST_F(PrepassMode, DepthModePassesPipelinesAndResources) {
    const FrameResult f = frame("atrium", {"prepass_mode=depth"});
    EXPECT_EQ(names(f),
              (std::vector<std::string>{"shadow", "depth_prepass", "normals_from_depth", "gtao",
                                        "ao_spatial", "ao_temporal", "contact_shadows", "forward",
                                        "skybox", "decals", "transparent", "tonemap"}));
    EXPECT_TRUE(f.skipped.empty());
    const PassResult& prepass = pass(f, "depth_prepass");
    ASSERT_EQ(prepass.pipelines.size(), 2u);
    if (const PipelineReport* opaque = pipeline(prepass, "depth_prepass opaque z-only")) {
        EXPECT_FALSE(opaque->fragment_stage);
        EXPECT_EQ(opaque->early_z, "guaranteed");
        EXPECT_GT(opaque->draws, 0u);
    }
    if (const PipelineReport* mask = pipeline(prepass, "depth_prepass mask z-only")) {
        EXPECT_TRUE(mask->fragment_stage);  // the alpha test
        EXPECT_EQ(mask->early_z, "lost: discard");
    }
    EXPECT_TRUE(prepass.writes == std::vector<std::string>{"depth"})
        << "the prepass writes depth only";
    // Forward computes normal and roughness itself, with one discard-free pipeline under EQUAL.
    const PassResult& forward = pass(f, "forward");
    ASSERT_EQ(forward.pipelines.size(), 1u);
    EXPECT_EQ(forward.pipelines[0].name, "forward opaque");
    EXPECT_EQ(forward.pipelines[0].early_z, "guaranteed");
    for (const char* absent : {"normals", "roughness"}) EXPECT_FALSE(has_resource(f, absent));
    EXPECT_TRUE(has_resource(f, "depth_normals"));

    const FrameResult plain =
        frame("atrium", {"prepass_mode=depth", "gtao=off", "contact_shadows=off"});
    EXPECT_EQ(names(plain),
              (std::vector<std::string>{"shadow", "depth_prepass", "forward", "skybox", "decals",
                                        "transparent", "tonemap"}));
    EXPECT_FALSE(has_resource(plain, "depth_normals")) << "nobody reads normals";
    EXPECT_EQ(plain.skipped, (std::vector<std::string>{"gtao: skipped (gtao=off)",
                                                       "ao_spatial: skipped (gtao=off)",
                                                       "ao_temporal: skipped (gtao=off)",
                                                       "contact_shadows: skipped "
                                                       "(contact_shadows=off)"}));
    const FrameResult gbuffer = frame("atrium", {});
    for (const char* present : {"normals", "roughness"})
        EXPECT_TRUE(has_resource(gbuffer, present));
    EXPECT_FALSE(has_resource(gbuffer, "depth_normals"));
    const std::vector<std::string> gbuffer_passes = names(gbuffer);
    EXPECT_EQ(std::count(gbuffer_passes.begin(), gbuffer_passes.end(), "normals_from_depth"), 0);
}

// Like for like (gtao and contact shadows off): the two prepass designs give the same image
// within rounding; forward's own normal and roughness equal what the G-buffer stored, up to
// the A2B10G10R10 / R8 quantisation.
TEST_F(PrepassMode, DepthModeImageMatchesGbufferWithoutScreenSpacePasses) {
    const auto [g, d] = both("atrium", {"gtao=off", "contact_shadows=off"});
    const size_t differ = differing_pixels(g, d, 8);
    std::printf("gtao/contact off: depth vs gbuffer differ in %zu pixels by > 8/255 (%.4f%%)\n",
                differ, percent(differ, g));
    EXPECT_LT(percent(differ, g), 0.5);
    ASSERT_TRUE(g.covered_pixels && d.covered_pixels);
    EXPECT_EQ(*g.covered_pixels, *d.covered_pixels);
}

// With GTAO and contact shadows, depth mode feeds them geometric normals reconstructed from
// depth instead of the G-buffer's normal-mapped ones: AO changes a little on normal-mapped
// surfaces and at silhouettes. Tolerance: < 3 % of pixels by > 8/255 (measured well below).
TEST_F(PrepassMode, ReconstructedNormalsKeepGtaoCloseToTheGbuffers) {
    const auto [g, d] = both("atrium", {});
    const size_t differ = differing_pixels(g, d, 8);
    std::printf("gtao/contact on: depth vs gbuffer differ in %zu pixels by > 8/255 (%.4f%%)\n",
                differ, percent(differ, g));
    EXPECT_LT(percent(differ, g), 3.0);
    // The reconstructed normals themselves: unit vectors where there is surface.
    const FrameResult n = frame("atrium", {"prepass_mode=depth"}, "depth_normals");
    ASSERT_TRUE(n.inspected);
    size_t surface = 0, unit = 0;
    for (size_t i = 0; i + 3 < n.inspected->texels.size(); i += 4) {
        if (n.inspected->texels[i + 3] == 0.0f) continue;  // background
        ++surface;
        float len2 = 0;
        for (int c = 0; c < 3; ++c) {
            const float v = n.inspected->texels[i + size_t(c)] * 2.0f - 1.0f;
            len2 += v * v;
        }
        unit += std::abs(len2 - 1.0f) < 0.03f;
    }
    EXPECT_EQ(surface, *n.covered_pixels);
    EXPECT_EQ(unit, surface);
}

// EQUAL keeps every visible fragment: the Z-only vertex stage (positions only) computes
// gl_Position bit for bit as forward's full one (same expression, `invariant`).
TEST_F(PrepassMode, ZOnlyPrepassKeepsEqualExact) {
    const auto [g, d] = both("atrium", {"equal_check=on"});
    ASSERT_TRUE(g.find<EqualCheckResult>() && d.find<EqualCheckResult>() && d.covered_pixels);
    EXPECT_EQ(d.find<EqualCheckResult>()->holes, g.find<EqualCheckResult>()->holes);
    EXPECT_EQ(d.find<EqualCheckResult>()->holes, 0u);
    EXPECT_EQ(d.find<EqualCheckResult>()->multiple, g.find<EqualCheckResult>()->multiple);
    const double fwd = double(*pass(d, "forward").shaded_fragments);
    EXPECT_GE(fwd, 0.98 * double(*d.covered_pixels));
    EXPECT_LE(fwd, 1.02 * double(*d.covered_pixels));
    // The prepass counts in depth mode through a count-only fragment stage (early tests): at
    // least one fragment per covered pixel, at most what it rasterized. Not the G-buffer
    // prepass's count: depth mode sorts whole groups, not instances (prepass_sort).
    const PassResult& prepass = pass(d, "depth_prepass");
    ASSERT_TRUE(prepass.shaded_fragments && prepass.rasterized_fragments);
    EXPECT_GE(*prepass.shaded_fragments, *d.covered_pixels);
    EXPECT_LE(*prepass.shaded_fragments, *prepass.rasterized_fragments);
}

// surface_id and what reads it (zfight, count_draws) give the same answers in both modes.
TEST_F(PrepassMode, SurfaceIdZfightAndDrawCountsWorkInDepthMode) {
    const auto ids = both("atrium", {"surface_id=on"}, "surface_id");
    ASSERT_TRUE(ids[0].inspected && ids[1].inspected);
    EXPECT_EQ(ids[0].inspected->texels, ids[1].inspected->texels);

    const auto fights = both("zfight", {"zfight=on"});
    ASSERT_TRUE(fights[0].find<ZfightResult>() && fights[1].find<ZfightResult>());
    EXPECT_GT(fights[1].find<ZfightResult>()->pixels, 0u);
    EXPECT_EQ(fights[0].find<ZfightResult>()->pixels, fights[1].find<ZfightResult>()->pixels);
    EXPECT_EQ(fights[0].find<ZfightResult>()->pairs.size(),
              fights[1].find<ZfightResult>()->pairs.size());

    const auto draws = both("atrium", {"count_draws=on"});
    ASSERT_EQ(passes::draws_of(draws[0]).draws.size(), passes::draws_of(draws[1]).draws.size());
    ASSERT_FALSE(passes::draws_of(draws[1]).draws.empty());
    // Visible pixels do not depend on the draw order; samples passed do (depth mode sorts
    // whole groups, the G-buffer prepass instances), so only their presence is compared.
    for (size_t i = 0; i < passes::draws_of(draws[0]).draws.size(); ++i) {
        EXPECT_EQ(passes::draws_of(draws[0]).draws[i].visible_pixels,
                  passes::draws_of(draws[1]).draws[i].visible_pixels)
            << i;
        EXPECT_EQ(passes::draws_of(draws[0]).draws[i].samples_passed.has_value(),
                  passes::draws_of(draws[1]).draws[i].samples_passed.has_value())
            << i;
    }
}

// The masked Z-only pipeline keeps its alpha test: the same discards, the same coverage.
TEST_F(PrepassMode, MaskedDiscardsAndPixelHistoryWorkInDepthMode) {
    const auto discards = both("foliage", {"count_discards=on"});
    ASSERT_TRUE(discards[0].find<DiscardCounts>() && discards[1].find<DiscardCounts>());
    EXPECT_EQ(discards[0].find<DiscardCounts>()->invoked,
              discards[1].find<DiscardCounts>()->invoked);
    EXPECT_EQ(discards[0].find<DiscardCounts>()->discarded,
              discards[1].find<DiscardCounts>()->discarded);
    EXPECT_EQ(discards[0].covered_pixels, discards[1].covered_pixels);

    // Overdraw, sorted: the front layer is the one prepass fragment that passes, and forward
    // (replayed against the prepass's depth) shades it once.
    const Settings s = test::settings_of({"prepass_mode=depth"});
    frame("overdraw", {"prepass_mode=depth"});  // loads the scene
    const PixelQuery at{kModeWidth / 2, kModeHeight / 2};
    const FrameResult f = renderer_->render(scene_.camera, s,
                                            {.width = kModeWidth,
                                             .height = kModeHeight,
                                             .read_back = ReadBack::No,
                                             .inspect = {},
                                             .pixel = at});
    ASSERT_TRUE(f.find<PixelHistory>());
    size_t prepass = 0, prepass_passed = 0, forward_passed = 0;
    for (const PixelFragment& p : f.find<PixelHistory>()->fragments) {
        if (p.pass == "depth_prepass") {
            ++prepass;
            prepass_passed += p.depth_passed;
            EXPECT_EQ(p.pipeline, "depth_prepass opaque z-only");
            EXPECT_FALSE(p.color);
        }
        if (p.pass == "forward") forward_passed += p.depth_passed;
    }
    EXPECT_EQ(prepass, 8u);  // overdraw_layers' default
    EXPECT_EQ(prepass_passed, 1u);
    EXPECT_EQ(forward_passed, 1u);
}

// msaa=4: no multisampled normals or roughness exist. The images differ only along MSAA edges:
// the G-buffer mode's forward reads the normal and roughness resolved (averaged over the
// pixel's samples, so mixing the surfaces at an edge), depth mode's computes each covering
// surface's own; so the differing pixels are a fraction of the frame's edge pixels (atrium
// 320x180: 1514 of 13530). Alpha to coverage still turns the masked prepass's alpha into coverage
// (through a colour slot without an image), giving the G-buffer mode's edges.
TEST_F(PrepassMode, MsaaAndAlphaToCoverageWorkInDepthMode) {
    if (!has_msaa4()) GTEST_SKIP() << "the device has no 4x";
    const auto ms = both("atrium", {"msaa=4", "gtao=off", "contact_shadows=off"});
    for (const char* absent : {"msaa_normals", "msaa_roughness", "normals"})
        EXPECT_FALSE(has_resource(ms[1], absent)) << absent;
    const size_t differ = differing_pixels(ms[0], ms[1], 8);
    ASSERT_TRUE(ms[1].msaa.edge_pixels);
    std::printf("msaa=4: depth vs gbuffer differ in %zu pixels (%.4f%%); %llu edge pixels\n",
                differ, percent(differ, ms[0]), (unsigned long long)*ms[1].msaa.edge_pixels);
    EXPECT_LT(double(differ), 0.5 * double(*ms[1].msaa.edge_pixels));
    EXPECT_LT(percent(differ, ms[0]), 5.0);

    const auto a2c = both("foliage", {"msaa=4", "alpha_to_coverage=on"});
    const FrameResult plain = frame("foliage", {"msaa=4", "prepass_mode=depth"});
    ASSERT_TRUE(a2c[0].msaa.edge_pixels && a2c[1].msaa.edge_pixels && plain.msaa.edge_pixels);
    std::printf("foliage 4x edge pixels: depth mode a2c off %llu, on %llu; gbuffer a2c %llu\n",
                (unsigned long long)*plain.msaa.edge_pixels,
                (unsigned long long)*a2c[1].msaa.edge_pixels,
                (unsigned long long)*a2c[0].msaa.edge_pixels);
    EXPECT_GT(double(*a2c[1].msaa.edge_pixels), 1.2 * double(*plain.msaa.edge_pixels));
    EXPECT_NEAR(double(*a2c[1].msaa.edge_pixels), double(*a2c[0].msaa.edge_pixels),
                0.05 * double(*a2c[0].msaa.edge_pixels));
    const PassResult& prepass = pass(a2c[1], "depth_prepass");
    EXPECT_TRUE(pipeline(prepass, "depth_prepass mask z-only a2c"));
}

// Every structural knob with depth mode, with and without counting: validation-clean (the
// fixture checks after each test; here after each frame too) and the same covered pixels.
TEST_F(PrepassMode, StructuralCombinationsInDepthModeAreValidationClean) {
    std::optional<uint64_t> covered;
    for (const char* compare : {"equal", "greater_or_equal"})
        for (const char* split : {"on", "off"})
            for (const char* reverse : {"on", "off"})
                for (const char* count : {"on", "off"}) {
                    const std::vector<std::string> s = {
                        "prepass_mode=depth", std::string("depth_compare=") + compare,
                        std::string("masked_split=") + split, std::string("reverse_z=") + reverse,
                        std::string("count_fragments=") + count};
                    SCOPED_TRACE(s[1] + " " + s[2] + " " + s[3] + " " + s[4]);
                    const FrameResult f = frame("atrium", s, "", 160, 90);
                    ASSERT_TRUE(f.covered_pixels);
                    if (!covered) covered = f.covered_pixels;
                    EXPECT_EQ(f.covered_pixels, covered);
                    EXPECT_EQ(renderer_->validation_message_count(), 0u);
                }
}

}  // namespace
