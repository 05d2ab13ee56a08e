// Pixel history through the Renderer facade, validation on: the fragments the instrumented
// replays record, in submission order, judged by the host's simulation of each pass's depth
// test, against what the scenes' geometry implies (overdraw's layers and their depths) and
// against independent counts of the real frame (the per-pixel count images, the HDR image).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "renderer/common/error.h"
#include "renderer/passes/pixel_history.h"
#include "renderer/renderer.h"
#include "renderer/scene/builtin/scene_facts.h"
#include "renderer/view/decode.h"
#include "tests/gpu/passes/shared_renderer.h"

namespace {

using namespace ds;
namespace facts = scene::builtin::facts;

constexpr uint32_t kWidth = 160, kHeight = 90;
constexpr int kLayers = 8;  // overdraw_layers' default

class PixelHistoryTest : public test::SceneSwitching {
  protected:
    FrameResult history(const std::string& scene, const std::vector<std::string>& settings,
                        PixelQuery at, const std::string& inspect = "") {
        const Settings s = test::settings_of(settings);
        if (scene != loaded_) {
            scene_ = scene::load_scene(scene, s);
            renderer_->set_scene(scene_);
            loaded_ = scene;
        }
        return renderer_->render(scene_.camera, s,
                                 {.width = kWidth,
                                  .height = kHeight,
                                  .read_back = ReadBack::Yes,
                                  .inspect = {{inspect}},
                                  .pixel = at});
    }
    // The HDR image's texel holds `written` as a half float: within one half step (the
    // conversion may round either way).
    static void expect_half_of(float texel, float written) {
        EXPECT_NEAR(texel, written, std::abs(written) * 0x1p-10f + 1e-6f);
    }
    static std::vector<PixelFragment> of_pass(const FrameResult& f, const std::string& pass) {
        std::vector<PixelFragment> out;
        for (const PixelFragment& p : f.find<PixelHistory>()->fragments)
            if (p.pass == pass) out.push_back(p);
        return out;
    }
    static float linear(const FrameResult& f, float depth) {
        return view::linear_depth(depth, f.depth->reverse_z, f.depth->znear, f.depth->zfar);
    }
    static float texel(const FrameResult& f, PixelQuery at, int channel = 0) {
        const InspectedImage& image = *f.inspected;
        return image.texels[(size_t(at.y) * image.width + at.x) * 4 + size_t(channel)];
    }
    std::string material(const PixelFragment& p) const {
        return scene_.instance_name(p.instance).material;
    }
};

// Any pixel: every layer covers the whole view (scene_facts.h).
constexpr PixelQuery kCentre{kWidth / 2 + 3, kHeight / 2 - 7};

// prepass off: forward draws the layers in authored order (farthest first), each nearer than
// the last, so all N pass; the last, the front layer, is the HDR image's colour.
TEST_F(PixelHistoryTest, OverdrawWithoutPrepassListsEveryLayerInAuthoredOrder) {
    const FrameResult f = history("overdraw", {"prepass=off"}, kCentre, "hdr");
    ASSERT_TRUE(f.find<PixelHistory>());
    EXPECT_EQ(f.find<PixelHistory>()->x, kCentre.x);
    EXPECT_EQ(f.find<PixelHistory>()->dropped, 0u);
    const std::vector<PixelFragment> forward = of_pass(f, "forward");
    ASSERT_EQ(forward.size(), size_t(kLayers));
    EXPECT_EQ(f.find<PixelHistory>()->fragments.size(), size_t(kLayers));  // nothing else covers it
    for (int i = 0; i < kLayers; ++i) {
        const PixelFragment& p = forward[size_t(i)];
        const int layer = kLayers - 1 - i;
        EXPECT_EQ(p.draw, uint32_t(i));
        EXPECT_EQ(material(p), "layer_" + std::to_string(layer));
        EXPECT_NEAR(linear(f, p.depth), facts::overdraw_layer_depth(layer), 1e-3f) << i;
        EXPECT_TRUE(p.depth_passed) << i;
        EXPECT_TRUE(p.shaded) << i;
        EXPECT_FALSE(p.alpha_test) << i;
        ASSERT_TRUE(p.color) << i;
        EXPECT_FALSE(p.blended) << i;
        // The test ran against the layer drawn before (the clear value for the first).
        EXPECT_EQ(p.against, i == 0 ? f.depth->reverse_z ? 0.0f : 1.0f : forward[i - 1].depth);
    }
    // The front layer's colour is what the frame's HDR image holds there (half floats).
    for (int c = 0; c < 4; ++c) expect_half_of(texel(f, kCentre, c), (*forward.back().color)[c]);
}

// prepass on, sorted: the prepass draws front to back, so the first fragment passes and the
// other N - 1 fail against it; forward rasterizes every layer under EQUAL and exactly the
// front one passes (and, early-Z, is the only one shaded).
TEST_F(PixelHistoryTest, OverdrawWithPrepassPassesTheFrontLayerOnce) {
    const FrameResult f = history("overdraw", {"prepass=on", "prepass_sort=on"}, kCentre, "hdr");
    ASSERT_TRUE(f.find<PixelHistory>());
    const std::vector<PixelFragment> prepass = of_pass(f, "depth_prepass");
    ASSERT_EQ(prepass.size(), size_t(kLayers));
    for (int i = 0; i < kLayers; ++i) {
        const PixelFragment& p = prepass[size_t(i)];
        EXPECT_EQ(material(p), "layer_" + std::to_string(i));  // front to back
        EXPECT_NEAR(linear(f, p.depth), facts::overdraw_layer_depth(i), 1e-3f) << i;
        EXPECT_EQ(p.depth_passed, i == 0) << i;
        EXPECT_EQ(p.shaded, i == 0) << i;  // the opaque prepass pipeline keeps early-Z
        EXPECT_EQ(p.against, i == 0 ? f.depth->reverse_z ? 0.0f : 1.0f : prepass[0].depth);
        EXPECT_FALSE(p.color) << i;  // the prepass writes no colour
    }
    const std::vector<PixelFragment> forward = of_pass(f, "forward");
    ASSERT_EQ(forward.size(), size_t(kLayers));
    const auto passing = std::count_if(forward.begin(), forward.end(),
                                       [](const PixelFragment& p) { return p.depth_passed; });
    const auto shaded = std::count_if(forward.begin(), forward.end(),
                                      [](const PixelFragment& p) { return p.shaded; });
    EXPECT_EQ(passing, 1);
    EXPECT_EQ(shaded, 1);
    for (const PixelFragment& p : forward) {
        EXPECT_EQ(p.against, prepass[0].depth);  // what the prepass left, read by the replay
        if (!p.depth_passed) continue;
        EXPECT_EQ(material(p), "layer_0");
        for (int c = 0; c < 4; ++c) expect_half_of(texel(f, kCentre, c), (*p.color)[c]);
    }
}

// msaa=4: one fragment per covered sample (every layer covers all four), each sample's depth
// test against that sample's own depth.
TEST_F(PixelHistoryTest, MsaaListsEverySampleOfEveryLayer) {
    const FrameResult f = history("overdraw", {"prepass=off", "msaa=4"}, kCentre);
    const std::vector<PixelFragment> forward = of_pass(f, "forward");
    ASSERT_EQ(forward.size(), size_t(kLayers) * 4);
    for (size_t i = 0; i < forward.size(); ++i) {
        const PixelFragment& p = forward[i];
        EXPECT_EQ(p.sample, i % 4) << i;
        EXPECT_EQ(material(p), "layer_" + std::to_string(kLayers - 1 - int(i / 4))) << i;
        EXPECT_TRUE(p.depth_passed) << i;
        if (i >= 4) {
            EXPECT_EQ(p.against, forward[i - 4].depth) << i;  // the same sample's
        }
    }
}

// Atrium's BLEND overlays (the decals pass's blend step, over forward's colour): at a pixel the
// frame's decal count image says an overlay was shaded, the simulated blending ends at the
// colour the frame's HDR image holds there (nothing draws over them there: no transparent
// draws, and the sky only where nothing is).
TEST_F(PixelHistoryTest, AtriumDecalBlendingEndsAtTheHdrColour) {
    const std::vector<std::string> settings = {"count_fragments=on"};
    const FrameResult counts = history("atrium", settings, {0, 0}, "decal_counts");
    ASSERT_TRUE(counts.inspected);
    std::optional<PixelQuery> decal;
    for (uint32_t i = 0; i < kWidth * kHeight && !decal; ++i)
        if (texel(counts, {i % kWidth, i / kWidth}) > 0) decal = PixelQuery{i % kWidth, i / kWidth};
    ASSERT_TRUE(decal) << "atrium has blended overlays in view";
    const FrameResult f = history("atrium", settings, *decal, "hdr");
    const PixelFragment* last = nullptr;
    for (const PixelFragment& p : f.find<PixelHistory>()->fragments) {
        if (p.pass != "decals" || !p.depth_passed) continue;
        ASSERT_TRUE(p.color);
        EXPECT_EQ(p.pipeline.rfind("decals blend", 0), 0u) << p.pipeline;
        ASSERT_TRUE(p.blended);
        last = &p;
    }
    ASSERT_NE(last, nullptr);
    for (int c = 0; c < 3; ++c) expect_half_of(texel(f, *decal, c), (*last->blended)[c]);
}

// Without a query the frame has no history pass and no history; with one, the frame's own
// passes and their results are the same.
TEST_F(PixelHistoryTest, OffAddsNothing) {
    const FrameResult queried = history("overdraw", {}, kCentre);
    const Settings s;
    const FrameResult off =
        renderer_->render(scene_.camera, s, {.width = kWidth, .height = kHeight});
    EXPECT_FALSE(off.find<PixelHistory>());
    for (const PassResult& p : off.passes) {
        EXPECT_NE(p.role, graph::PassRole::History) << p.name;
        EXPECT_EQ(p.name.find("history"), std::string::npos) << p.name;
    }
    EXPECT_EQ(test::names(queried), test::names(off));
    EXPECT_EQ(queried.rgba8, off.rgba8);  // the replay draws nothing into the frame
    std::vector<std::string> replays;
    for (const PassResult& p : queried.passes)
        if (p.role == graph::PassRole::History) replays.push_back(p.name);
    // Each geometry pass's replay right before it (transparent runs with nothing to draw).
    const std::vector<std::string> expected = {"depth_prepass_history", "forward_history",
                                               "transparent_history"};
    EXPECT_EQ(replays, expected);
    const PixelQuery outside{kWidth, 0};
    EXPECT_THROW(renderer_->render(scene_.camera, s,
                                   {.width = kWidth,
                                    .height = kHeight,
                                    .read_back = ReadBack::Yes,
                                    .inspect = {},
                                    .pixel = outside}),
                 ds::Error);
}

// Diagnostics together: the counts of a frame with a history (whose replays come before each
// geometry pass, and its measurement draws after) are its passes' own, as without one.
TEST_F(PixelHistoryTest, CountsStayThePassesOwnWithAHistory) {
    const std::vector<std::string> counting = {"count_fragments=on", "count_draws=on"};
    const FrameResult queried = history("foliage", counting, kCentre);
    const Settings s = test::settings_of(counting);
    const FrameResult off =
        renderer_->render(scene_.camera, s, {.width = kWidth, .height = kHeight});
    ASSERT_TRUE(queried.find<PixelHistory>());
    auto by_name = [](const FrameResult& f, const std::string& name) -> const PassResult& {
        for (const PassResult& p : f.passes)
            if (p.name == name && p.role == graph::PassRole::Frame) return p;
        static const PassResult none;
        ADD_FAILURE() << "no pass " << name;
        return none;
    };
    for (const char* name : {"shadow", "depth_prepass", "forward", "transparent"}) {
        const PassResult& with = by_name(queried, name);
        const PassResult& without = by_name(off, name);
        ASSERT_TRUE(with.shaded_fragments) << name;
        EXPECT_EQ(with.shaded_fragments, without.shaded_fragments) << name;
        EXPECT_EQ(with.rasterized_fragments, without.rasterized_fragments) << name;
        EXPECT_EQ(with.discarded_fragments, without.discarded_fragments) << name;
        EXPECT_EQ(with.draw_shaded, without.draw_shaded) << name;
        EXPECT_EQ(with.pipelines.size(), without.pipelines.size()) << name;
    }
    for (const PassResult& p : queried.passes) {
        if (p.role != graph::PassRole::Frame) {
            EXPECT_FALSE(p.shaded_fragments) << p.name;
        }
    }
}

// Foliage: a pixel where the masked prepass discarded (derived from the frame's own discard
// count image) lists that many masked prepass fragments with alpha below the cutoff, each
// shaded (the discard costs the pipeline its early-Z), and as many shaded prepass fragments as
// the frame's count image says ran there.
TEST_F(PixelHistoryTest, FoliageCutOutIsADiscardedMaskedFragment) {
    const std::vector<std::string> settings = {"count_fragments=on"};
    const FrameResult counts = history("foliage", settings, {0, 0}, "prepass_discarded");
    ASSERT_TRUE(counts.inspected);
    std::optional<PixelQuery> cut;
    for (uint32_t y = 0; y < kHeight && !cut; ++y)
        for (uint32_t x = 0; x < kWidth && !cut; ++x)
            if (texel(counts, {x, y}) > 0) cut = PixelQuery{x, y};
    ASSERT_TRUE(cut) << "foliage discards somewhere";
    const uint32_t discarded = uint32_t(texel(counts, *cut));

    const FrameResult f = history("foliage", settings, *cut, "prepass_counts");
    const std::vector<PixelFragment> prepass = of_pass(f, "depth_prepass");
    uint32_t cut_away = 0, shaded = 0;
    for (const PixelFragment& p : prepass) {
        shaded += p.shaded;
        if (!p.alpha_test || p.alpha_test->passed) continue;
        ++cut_away;
        EXPECT_LT(p.alpha_test->alpha, p.alpha_test->cutoff);
        EXPECT_FLOAT_EQ(p.alpha_test->cutoff, facts::kFoliageAlphaCutoff);
        EXPECT_TRUE(p.shaded);
        EXPECT_NE(p.pipeline.find("depth_prepass mask"), std::string::npos) << p.pipeline;
    }
    EXPECT_EQ(cut_away, discarded);
    EXPECT_EQ(shaded, uint32_t(texel(f, *cut)));
}

}  // namespace

namespace {

// simulate() alone, on made-up records (no device): the order it restores, the depth rules,
// unorm quantisation, duplicates, blending.
passes::HistoryRecord record(uint32_t instance, uint32_t primitive, float depth,
                             uint32_t flags = passes::kHistoryColor) {
    passes::HistoryRecord r;
    r.instance = instance;
    r.primitive = primitive;
    r.depth = depth;
    r.flags = flags;
    r.color = {1.0f, 0.5f, 0.25f, 0.5f};
    r.dst = {0.0f, 0.0f, 1.0f, 1.0f};
    return r;
}

TEST(PixelHistorySimulate, RestoresSubmissionOrderAndAppliesTheDepthRules) {
    passes::DrawLog log;
    log.add(5, 1);  // draw 0: instance 5
    log.pipeline = 1;
    log.add(0, 3);  // draw 1: instances 0..2, the second pipeline
    const std::vector<passes::HistoryRecord> records = {
        record(1, 0, 0.6f), record(0, 2, 0.4f), record(5, 0, 0.5f),
        record(0, 1, 0.7f), record(0, 1, 0.7f),  // a repeated store: one fragment
        record(9, 0, 0.9f)};                     // no draw of the log holds instance 9: dropped
    const passes::HistoryPipeline pipelines[] = {{"a", true, false}, {"b", false, false}};
    const auto out = passes::simulate("forward", records, log, pipelines,
                                      {.compare = VK_COMPARE_OP_GREATER,
                                       .depth_write = true,
                                       .clear_depth = 0.0f,
                                       .depth_format = VK_FORMAT_D32_SFLOAT});
    ASSERT_EQ(out.size(), 4u);
    const uint32_t instances[] = {5, 0, 0, 1}, primitives[] = {0, 1, 2, 0};
    const bool passed[] = {true, true, false, false};
    const float against[] = {0.0f, 0.5f, 0.7f, 0.7f};
    for (size_t i = 0; i < out.size(); ++i) {
        EXPECT_EQ(out[i].instance, instances[i]) << i;
        EXPECT_EQ(out[i].primitive, primitives[i]) << i;
        EXPECT_EQ(out[i].depth_passed, passed[i]) << i;
        EXPECT_EQ(out[i].against, against[i]) << i;
    }
    EXPECT_TRUE(out[0].shaded);  // early-Z and passed
    EXPECT_TRUE(out[2].shaded);  // late (pipeline b): ran although it failed
    EXPECT_EQ(out[1].draw, 1u);
    EXPECT_EQ(out[1].pipeline, "b");
}

TEST(PixelHistorySimulate, QuantisesUnormDepthsAndBlendsInOrder) {
    passes::DrawLog log;
    log.add(0, 2);
    // Two D16 depths one hundredth of a step apart are the same stored value: EQUAL passes.
    const float step = 1.0f / 65535.0f;
    std::vector<passes::HistoryRecord> records = {record(0, 0, 100.0f * step),
                                                  record(1, 0, 100.01f * step)};
    records[0].start_depth = records[1].start_depth = 100.0f * step;
    const passes::HistoryPipeline blended[] = {{"t", true, true}};
    const auto out =
        passes::simulate("transparent", records, log, blended,
                         {.compare = VK_COMPARE_OP_EQUAL, .depth_format = VK_FORMAT_D16_UNORM});
    ASSERT_EQ(out.size(), 2u);
    EXPECT_TRUE(out[0].depth_passed);
    EXPECT_TRUE(out[1].depth_passed);
    ASSERT_TRUE(out[0].blended && out[1].blended);
    // src 0.5 alpha over dst (0, 0, 1, 1): colour src * 0.5 + dst * 0.5, alpha 0.5 + 1 * 0.5.
    EXPECT_FLOAT_EQ((*out[0].blended)[0], 0.5f);
    EXPECT_FLOAT_EQ((*out[0].blended)[2], 0.625f);
    EXPECT_FLOAT_EQ((*out[0].blended)[3], 1.0f);
    // The second blends over the first's result.
    EXPECT_FLOAT_EQ((*out[1].blended)[0], 0.75f);
    EXPECT_FLOAT_EQ((*out[1].blended)[2], 0.4375f);
}

// A discarded fragment keeps its alpha test, writes nothing and has no colour.
TEST(PixelHistorySimulate, DiscardedFragmentsWriteNothing) {
    passes::DrawLog log;
    log.add(0, 2);
    passes::HistoryRecord cut =
        record(0, 0, 0.8f, passes::kHistoryAlphaTested | passes::kHistoryDiscarded);
    cut.alpha = 0.2f;
    cut.cutoff = 0.5f;
    const std::vector<passes::HistoryRecord> records = {cut, record(1, 0, 0.3f)};
    const passes::HistoryPipeline late[] = {{"mask", false, false}};
    const auto out = passes::simulate(
        "depth_prepass", records, log, late,
        {.compare = VK_COMPARE_OP_GREATER, .depth_write = true, .clear_depth = 0.0f});
    ASSERT_EQ(out.size(), 2u);
    ASSERT_TRUE(out[0].alpha_test);
    EXPECT_FALSE(out[0].alpha_test->passed);
    EXPECT_TRUE(out[0].shaded);
    EXPECT_FALSE(out[0].color);
    EXPECT_TRUE(out[1].depth_passed);  // the discarded nearer fragment left the clear value
    EXPECT_EQ(out[1].against, 0.0f);
}

}  // namespace
