// count_draws=on through the Renderer facade, validation on: per draw group, visible pixels
// (surface_id's histogram), samples passed (precise occlusion queries in the pass that decides
// visibility) and shaded fragments per counting pass, against what the scenes' geometry
// implies; the diagnostic off leaves the frame as it was.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "capture/report.h"
#include "renderer/passes/draw_counts.h"
#include "renderer/renderer.h"
#include "tests/gpu/passes/shared_renderer.h"

namespace {

using namespace ds;

constexpr uint32_t kDrawsWidth = 320, kDrawsHeight = 180;
constexpr uint64_t kDrawsPixels = uint64_t(kDrawsWidth) * kDrawsHeight;
constexpr int kLayers = 8;  // overdraw_layers' default

class DrawCounts : public test::SceneSwitching {
  protected:
    FrameResult render(const std::string& scene_name, const std::vector<std::string>& settings,
                       ReadBack read_back = ReadBack::No) {
        return SceneSwitching::render(scene_name, settings, kDrawsWidth, kDrawsHeight, read_back);
    }
    static uint64_t shaded(const DrawReport& d, const std::string& pass) {
        for (const auto& [name, n] : d.shaded_fragments)
            if (name == pass) return n;
        ADD_FAILURE() << d.name.mesh << " has no shaded count for " << pass;
        return 0;
    }
    // The overdraw scene's layers by k (layer_0 the nearest), from their mesh names.
    static std::map<int, const DrawReport*> layers(const FrameResult& f) {
        std::map<int, const DrawReport*> out;
        for (const DrawReport& d : passes::draws_of(f).draws)
            out[std::stoi(d.name.mesh.substr(6))] = &d;
        EXPECT_EQ(out.size(), size_t(kLayers));
        return out;
    }
};

// N view-filling layers, authored farthest first. Only the front layer is visible. The
// prepass decides visibility: sorted front to back, the front layer passes every pixel and
// the others none; in authored order each layer is nearer than everything before it, so each
// passes every pixel. Without the prepass forward's queries see the authored order too.
TEST_F(DrawCounts, OverdrawLayersPassAsTheirDrawOrderImplies) {
    const FrameResult sorted = render("overdraw", {"count_draws=on"});
    ASSERT_EQ(passes::draws_of(sorted).draws.size(), size_t(kLayers));
    EXPECT_EQ(passes::draws_of(sorted).samples_pass, "depth_prepass");
    EXPECT_EQ(passes::draws_of(sorted).visible_note, "");
    for (const auto& [k, d] : layers(sorted)) {
        const uint64_t front = k == 0 ? kDrawsPixels : 0;
        EXPECT_EQ(d->visible_pixels, front) << k;
        EXPECT_EQ(d->samples_passed, front) << k;
        EXPECT_EQ(d->occluded, k != 0) << k;
        EXPECT_EQ(shaded(*d, "depth_prepass"), front) << k;  // early tests: only what passes
        EXPECT_EQ(shaded(*d, "forward"), front) << k;        // EQUAL
        // Waste only where a pass shaded the draw: none at all here.
        for (const auto& [pass, n] : d->wasted_fragments) EXPECT_EQ(n, 0) << k << " " << pass;
        EXPECT_EQ(d->wasted_fragments.size(), k == 0 ? 2u : 0u) << k;  // prepass, forward
        EXPECT_EQ(d->instances, 1u);
        EXPECT_EQ(d->name.node, d->name.mesh);
    }
    const FrameResult authored = render("overdraw", {"count_draws=on", "prepass_sort=off"});
    for (const auto& [k, d] : layers(authored)) {
        EXPECT_EQ(d->visible_pixels, k == 0 ? kDrawsPixels : 0) << k;
        EXPECT_EQ(d->samples_passed, kDrawsPixels) << k;
        EXPECT_EQ(shaded(*d, "depth_prepass"), kDrawsPixels) << k;
        ASSERT_FALSE(d->wasted_fragments.empty()) << k;
        EXPECT_EQ(d->wasted_fragments[0], (std::pair<std::string, int64_t>{
                                              "depth_prepass", k == 0 ? 0 : int64_t(kDrawsPixels)}))
            << k;
        EXPECT_EQ(d->occluded, k != 0) << k;
    }
    const FrameResult off = render("overdraw", {"count_draws=on", "prepass=off"});
    EXPECT_EQ(passes::draws_of(off).samples_pass, "forward");
    EXPECT_NE(passes::draws_of(off).visible_note, "");
    EXPECT_TRUE(passes::draws_of(off).draw_pixels.empty());
    for (const auto& [k, d] : layers(off)) {
        EXPECT_EQ(d->visible_pixels, std::nullopt) << k;
        EXPECT_EQ(d->samples_passed, kDrawsPixels) << k;
        EXPECT_EQ(shaded(*d, "forward"), kDrawsPixels) << k;
        EXPECT_TRUE(d->wasted_fragments.empty()) << k;
        EXPECT_FALSE(d->occluded) << k;  // each layer passed when it was drawn
    }
}

// Atrium: visible pixels partition the covered pixels; per pass the per-draw shaded counts
// add up to the pass's own total; a draw's samples passed are at least its visible pixels
// (its last depth write won each of them); BLEND groups, which the prepass does not draw,
// have neither.
TEST_F(DrawCounts, AtriumDrawsAddUpToThePassesAndTheCoverage) {
    const FrameResult f = render("atrium", {"count_draws=on"});
    ASSERT_FALSE(passes::draws_of(f).draws.empty());
    ASSERT_TRUE(f.covered_pixels);
    uint64_t visible = 0, occluded = 0;
    std::map<std::string, uint64_t> per_pass;
    for (const DrawReport& d : passes::draws_of(f).draws) {
        visible += d.visible_pixels.value_or(0);
        occluded += d.occluded;
        for (const auto& [pass, n] : d.shaded_fragments) per_pass[pass] += n;
        EXPECT_EQ(d.visible_pixels.has_value(), d.samples_passed.has_value()) << d.name.mesh;
        if (d.visible_pixels) {
            EXPECT_GE(*d.samples_passed, *d.visible_pixels) << d.name.mesh;
        }
        if (d.alpha_mode == "blend") {
            EXPECT_FALSE(d.samples_passed) << d.name.mesh;
        }
    }
    EXPECT_EQ(visible, *f.covered_pixels);
    EXPECT_GT(occluded, 0u);         // the atrium hides some of its draws from its own camera
    EXPECT_EQ(per_pass.size(), 5u);  // shadow, depth_prepass, forward, decals, transparent
    for (const PassResult& p : f.passes) {
        if (!p.shaded_fragments) continue;
        EXPECT_EQ(per_pass[p.name], *p.shaded_fragments) << p.name;
    }
    // The pixel map agrees with the histogram.
    ASSERT_EQ(passes::draws_of(f).draw_pixels.size(), kDrawsPixels);
    std::vector<uint64_t> from_map(passes::draws_of(f).draws.size() + 1, 0);
    for (uint32_t g : passes::draws_of(f).draw_pixels) ++from_map.at(g);
    for (const DrawReport& d : passes::draws_of(f).draws) {
        if (d.visible_pixels) {
            EXPECT_EQ(from_map[d.group + 1], *d.visible_pixels);
        }
    }
}

// Off means free: no pass, no per-draw data, and the image does not move when it is on.
TEST_F(DrawCounts, OffAddsNothingAndOnLeavesTheImageAlone) {
    const FrameResult off = render("atrium", {}, ReadBack::Yes);
    const FrameResult on = render("atrium", {"count_draws=on"}, ReadBack::Yes);
    EXPECT_TRUE(passes::draws_of(off).draws.empty());
    EXPECT_TRUE(passes::draws_of(off).draw_pixels.empty());
    for (const PassResult& p : off.passes) {
        EXPECT_NE(p.name, "readback_draws");
        EXPECT_TRUE(p.draw_shaded.empty()) << p.name;
        EXPECT_TRUE(p.draw_samples_passed.empty()) << p.name;
    }
    EXPECT_EQ(test::names(off), test::names(on));  // the frame's own passes are the same
    ASSERT_EQ(on.rgba8.size(), off.rgba8.size());
    EXPECT_TRUE(on.rgba8 == off.rgba8);
}

// At msaa 4 the queries count samples and surface_id is sample 0's winner: the report says so,
// and the counts still add up per pass.
TEST_F(DrawCounts, MultisampledFramesCountSamplesAndSaySo) {
    const FrameResult f = render("overdraw", {"count_draws=on", "msaa=4"});
    EXPECT_NE(passes::draws_of(f).visible_note, "");
    for (const auto& [k, d] : layers(f))
        EXPECT_EQ(d->samples_passed, k == 0 ? 4 * kDrawsPixels : 0);
}

}  // namespace
