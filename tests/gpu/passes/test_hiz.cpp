// hiz=on through the Renderer facade, validation on: every level of the Hi-Z pyramid read back
// and checked texel by texel against a CPU reduction of the level below (even and odd sizes,
// both depth directions, msaa 1 and 4: level 0 against the depth, or every depth sample);
// with count_draws the per-draw verdicts against the occlusion queries and visible pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "capture/report.h"
#include "renderer/passes/draw_counts.h"
#include "renderer/passes/hiz.h"
#include "renderer/renderer.h"
#include "tests/gpu/passes/shared_renderer.h"

namespace {

using namespace ds;

// A level as read back: the r channel of the inspect pass's RGBA32F texels.
struct Level {
    uint32_t width = 0, height = 0;
    std::vector<float> d;
    float at(uint32_t x, uint32_t y) const { return d[size_t(y) * width + x]; }
};

Level level_of(const InspectedImage& image) {
    Level out{image.width, image.height, {}};
    for (size_t i = 0; i < size_t(image.width) * image.height; ++i)
        out.d.push_back(image.texels[i * 4]);
    return out;
}

float farther(float a, float b, bool reverse_z) {
    return reverse_z ? std::min(a, b) : std::max(a, b);
}

// The rule written out independently of the shader: the next level is max(1, floor(size / 2));
// child x covers parent 2x and 2x+1 (clamped), the last child also the parent's last column
// when the parent is odd (likewise rows).
Level reduce(const Level& p, bool reverse_z) {
    Level c{std::max(p.width / 2, 1u), std::max(p.height / 2, 1u), {}};
    c.d.resize(size_t(c.width) * c.height);
    for (uint32_t y = 0; y < c.height; ++y) {
        for (uint32_t x = 0; x < c.width; ++x) {
            const uint32_t x1 = x + 1 == c.width ? p.width - 1 : std::min(2 * x + 1, p.width - 1);
            const uint32_t y1 =
                y + 1 == c.height ? p.height - 1 : std::min(2 * y + 1, p.height - 1);
            float v = p.at(2 * x, 2 * y);
            for (uint32_t py = 2 * y; py <= y1; ++py)
                for (uint32_t px = 2 * x; px <= x1; ++px) v = farther(v, p.at(px, py), reverse_z);
            c.d[size_t(y) * c.width + x] = v;
        }
    }
    return c;
}

class Hiz : public test::SceneSwitching {
  protected:
    // Renders with hiz=on and reads back `depth` (when not empty) and every level.
    FrameResult render_levels(const std::string& scene, std::vector<std::string> settings,
                              uint32_t w, uint32_t h, ReadBack read_back, bool with_depth) {
        settings.push_back("hiz=on");
        const Settings s = test::settings_of(settings);
        if (scene != loaded_) {
            scene_ = scene::load_scene(scene, s);
            renderer_->set_scene(scene_);
            loaded_ = scene;
        }
        std::vector<InspectRequest> asks;
        for (uint32_t k = 0; k < 16; ++k) asks.push_back({"hiz." + std::to_string(k)});
        if (with_depth) asks.insert(asks.begin(), InspectRequest{"depth"});
        return renderer_->render(
            scene_.camera, s, {.width = w, .height = h, .read_back = read_back, .inspect = asks});
    }
    static const InspectedImage* image(const FrameResult& f, const std::string& name) {
        if (f.inspected && f.inspected->name == name) return &*f.inspected;
        for (const InspectedImage& i : f.overlays)
            if (i.name == name) return &i;
        return nullptr;
    }
    // Every level k+1 is the CPU reduction of level k (read back), exactly; returns the levels.
    static std::vector<Level> check_levels(const FrameResult& f, bool reverse_z) {
        std::vector<Level> levels;
        EXPECT_TRUE((f.find<HizResult>() != nullptr));
        if (!f.find<HizResult>()) return levels;
        uint32_t w = f.width, h = f.height;
        for (size_t k = 0; k < f.find<HizResult>()->levels.size(); ++k) {
            EXPECT_EQ(f.find<HizResult>()->levels[k], (std::pair<uint32_t, uint32_t>{w, h})) << k;
            const InspectedImage* img = image(f, "hiz." + std::to_string(k));
            if (!img) {
                ADD_FAILURE() << "hiz." << k << " not read back";
                return levels;
            }
            EXPECT_EQ(img->semantic,
                      reverse_z ? graph::Semantic::ReverseZDepth : graph::Semantic::ForwardZDepth);
            levels.push_back(level_of(*img));
            EXPECT_EQ(levels.back().width, w);
            EXPECT_EQ(levels.back().height, h);
            if (k > 0) {
                const Level want = reduce(levels[k - 1], reverse_z);
                size_t wrong = 0;
                for (size_t i = 0; i < want.d.size(); ++i) wrong += want.d[i] != levels[k].d[i];
                EXPECT_EQ(wrong, 0u) << "level " << k << " (" << w << "x" << h << ")";
            }
            w = std::max(w / 2, 1u);
            h = std::max(h / 2, 1u);
        }
        EXPECT_EQ(f.find<HizResult>()->levels.back(), (std::pair<uint32_t, uint32_t>{1, 1}));
        EXPECT_EQ(image(f, "hiz." + std::to_string(f.find<HizResult>()->levels.size())), nullptr);
        return levels;
    }
};

// The atrium (sky and geometry at many depths) at even and odd sizes, both directions: level 0
// is the depth itself, and each level above is the farthest of its children, exactly.
TEST_F(Hiz, EveryLevelIsTheFarthestOfItsChildren) {
    const std::vector<std::pair<uint32_t, uint32_t>> sizes = {{64, 64}, {67, 45}, {37, 23}};
    for (const bool reverse_z : {true, false}) {
        for (const auto& [w, h] : sizes) {
            SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h) +
                         (reverse_z ? " reverse-Z" : " forward-Z"));
            const std::string rz = reverse_z ? "reverse_z=on" : "reverse_z=off";
            const FrameResult f = render_levels("atrium", {rz}, w, h, ReadBack::No, true);
            const std::vector<Level> levels = check_levels(f, reverse_z);
            ASSERT_FALSE(levels.empty());
            const InspectedImage* depth = image(f, "depth");
            ASSERT_NE(depth, nullptr);
            EXPECT_EQ(levels[0].d, level_of(*depth).d);
            EXPECT_EQ(f.find<HizResult>()->source, "depth");
            // Not a flat image: sky (far) and geometry both reach level 0, and the 1x1 level
            // holds the far value (some sky is in view).
            const float far = reverse_z ? 0.0f : 1.0f;
            EXPECT_NE(std::count(levels[0].d.begin(), levels[0].d.end(), far), 0);
            EXPECT_NE(std::count(levels[0].d.begin(), levels[0].d.end(), far),
                      std::ptrdiff_t(levels[0].d.size()));
            EXPECT_EQ(levels.back().d, std::vector<float>{far});
        }
    }
}

// At msaa 4 level 0 is the farthest of each pixel's four depth samples (every sample read back
// by msaa_probe), not the resolved (nearest) depth; the levels above follow the same rule.
TEST_F(Hiz, MultisampledLevelZeroIsTheFarthestSample) {
    for (const bool reverse_z : {true, false}) {
        SCOPED_TRACE(reverse_z ? "reverse-Z" : "forward-Z");
        const std::string rz = reverse_z ? "reverse_z=on" : "reverse_z=off";
        const FrameResult f =
            render_levels("edges", {rz, "msaa=4"}, 67, 45, ReadBack::WithMsaaDepth, false);
        const std::vector<Level> levels = check_levels(f, reverse_z);
        ASSERT_FALSE(levels.empty());
        EXPECT_EQ(f.find<HizResult>()->source, "msaa_depth");
        EXPECT_EQ(f.find<HizResult>()->samples, 4u);
        const std::vector<float>& samples = f.msaa.depth_samples;
        ASSERT_EQ(samples.size(), size_t(67) * 45 * 4);
        size_t wrong = 0, differs_from_nearest = 0;
        for (size_t p = 0; p < levels[0].d.size(); ++p) {
            float far = samples[p * 4], near = samples[p * 4];
            for (size_t s = 1; s < 4; ++s) {
                far = farther(far, samples[p * 4 + s], reverse_z);
                near = farther(near, samples[p * 4 + s], !reverse_z);
            }
            wrong += levels[0].d[p] != far;
            differs_from_nearest += far != near;
        }
        EXPECT_EQ(wrong, 0u);
        EXPECT_GT(differs_from_nearest, 0u);  // edge pixels: the choice of sample matters
    }
}

constexpr uint32_t kDrawsW = 320, kDrawsH = 180;
constexpr uint64_t kDrawsPixels = uint64_t(kDrawsW) * kDrawsH;

// The overdraw scene's layers by k (layer_0 the nearest), from their mesh names.
std::map<int, const DrawReport*> overdraw_layers(const FrameResult& f) {
    std::map<int, const DrawReport*> out;
    for (const DrawReport& d : passes::draws_of(f).draws)
        out[std::stoi(d.name.mesh.substr(6))] = &d;
    return out;
}

// Overdraw: eight view-filling layers. Sorted front to back, the back layers' queries pass
// nothing and Hi-Z finds them occluded; the front layer is visible to both. In authored order
// (farthest first) every layer's query passes W x H samples when drawn, while the final depth
// hides all but the front one: Hi-Z's verdict is the same, and the check reports those seven
// as disagreeing with samples_passed, but never with the pixels they won.
TEST_F(Hiz, OverdrawBackLayersAreOccludedAndPassNoSamples) {
    for (const bool reverse_z : {true, false}) {
        SCOPED_TRACE(reverse_z ? "reverse-Z" : "forward-Z");
        const std::string rz = reverse_z ? "reverse_z=on" : "reverse_z=off";
        const FrameResult f =
            render("overdraw", {"count_draws=on", "hiz=on", rz}, kDrawsW, kDrawsH, ReadBack::No);
        ASSERT_TRUE((f.find<HizResult>() != nullptr));
        const std::map<int, const DrawReport*> layers = overdraw_layers(f);
        ASSERT_EQ(layers.size(), 8u);
        for (const auto& [k, d] : layers) {
            ASSERT_TRUE(d->hiz.has_value()) << k;
            EXPECT_EQ(*d->hiz, k == 0 ? HizVerdict::Visible : HizVerdict::Occluded) << k;
            EXPECT_EQ(d->hiz_occluded_instances, k == 0 ? 0u : 1u) << k;
            EXPECT_EQ(d->samples_passed, k == 0 ? kDrawsPixels : 0u) << k;
            EXPECT_FALSE(d->hiz_unsafe) << k;
        }
        EXPECT_EQ(f.find<HizResult>()->unsafe, 0u);
        EXPECT_EQ(f.find<HizResult>()->unsafe_visible, 0u);
        // Each occluded layer covers the whole view: tested at the first level at most 2x2
        // texels (2x1 for 320x180), against the front layer's depth.
        ASSERT_EQ(f.find<HizResult>()->instances.size(), 8u);
        const float front =
            layers.at(0)->hiz ? f.find<HizResult>()->instances[layers.at(0)->first_instance].nearest
                              : 0.0f;
        for (const auto& [k, d] : layers) {
            const HizInstance& i = f.find<HizResult>()->instances[d->first_instance];
            if (k == 0) continue;
            EXPECT_EQ(f.find<HizResult>()->levels.at(i.level),
                      (std::pair<uint32_t, uint32_t>{2, 1}))
                << k;
            EXPECT_TRUE(reverse_z ? i.nearest < i.farthest : i.nearest > i.farthest) << k;
            EXPECT_NEAR(i.farthest, front, 1e-5f) << k;
        }
    }
    const FrameResult authored =
        render("overdraw", {"count_draws=on", "hiz=on", "prepass_sort=off"}, kDrawsW, kDrawsH,
               ReadBack::No);
    ASSERT_TRUE((authored.find<HizResult>() != nullptr));
    for (const auto& [k, d] : overdraw_layers(authored)) {
        EXPECT_EQ(d->hiz, k == 0 ? HizVerdict::Visible : HizVerdict::Occluded) << k;
        EXPECT_EQ(d->samples_passed, kDrawsPixels) << k;
        EXPECT_EQ(d->hiz_unsafe, k != 0) << k;
        EXPECT_EQ(d->visible_pixels, k == 0 ? kDrawsPixels : 0u) << k;
    }
    EXPECT_EQ(authored.find<HizResult>()->unsafe, 7u);
    EXPECT_EQ(authored.find<HizResult>()->unsafe_visible, 0u);
}

// Every built-in scene, sorted prepass, both directions and msaa 4: no draw that Hi-Z calls
// occluded or outside passed samples or won a pixel; the report carries the verdicts.
TEST_F(Hiz, NoDrawIsHiddenByHizAndSeenByItsQueries) {
    const std::vector<std::vector<std::string>> variants = {{}, {"reverse_z=off"}, {"msaa=4"}};
    for (const char* scene : {"atrium", "overdraw", "zfight", "foliage", "edges", "decals"}) {
        for (const std::vector<std::string>& variant : variants) {
            std::vector<std::string> settings = {"count_draws=on", "hiz=on"};
            settings.insert(settings.end(), variant.begin(), variant.end());
            SCOPED_TRACE(std::string(scene) + " " + (variant.empty() ? "" : variant[0]));
            const FrameResult f = render(scene, settings, 297, 210, ReadBack::No);
            ASSERT_TRUE((f.find<HizResult>() != nullptr));
            ASSERT_FALSE(passes::draws_of(f).draws.empty());
            EXPECT_EQ(f.find<HizResult>()->unsafe, 0u);
            EXPECT_EQ(f.find<HizResult>()->unsafe_visible, 0u);
            for (const DrawReport& d : passes::draws_of(f).draws) {
                ASSERT_TRUE(d.hiz.has_value()) << d.name.mesh;
                if (*d.hiz != HizVerdict::Visible) {
                    EXPECT_EQ(d.samples_passed.value_or(0), 0u) << d.name.mesh;
                    EXPECT_EQ(d.visible_pixels.value_or(0), 0u) << d.name.mesh;
                }
            }
        }
    }
}

// The atrium's own camera hides near_wall and loggia_roof (count_draws' occluded draws): Hi-Z
// finds at least one of them, and a capture's report carries the verdict beside samples_passed.
TEST_F(Hiz, ReportCarriesTheVerdictsNextToSamplesPassed) {
    const Settings s = test::settings_of({"count_draws=on", "hiz=on"});
    const FrameResult f = render("atrium", {"count_draws=on", "hiz=on"}, 640, 360, ReadBack::Yes);
    ASSERT_TRUE((f.find<HizResult>() != nullptr));
    size_t occluded = 0;
    for (const DrawReport& d : passes::draws_of(f).draws) occluded += d.hiz == HizVerdict::Occluded;
    EXPECT_GT(occluded, 0u);
    const nlohmann::json r =
        capture::frame_report({.device = {}, .scene = scene_, .settings = s, .frame = f});
    ASSERT_TRUE(r.contains("hiz"));
    EXPECT_EQ(r["hiz"]["levels"].size(), f.find<HizResult>()->levels.size());
    EXPECT_EQ(r["hiz"]["unsafe_draws"], 0);
    EXPECT_EQ(r["hiz"]["draws"]["occluded"], occluded);
    for (size_t i = 0; i < passes::draws_of(f).draws.size(); ++i) {
        const nlohmann::json& d = r["draws"][i];
        EXPECT_EQ(d["hiz"], hiz_verdict_name(*passes::draws_of(f).draws[i].hiz));
        EXPECT_TRUE(d.contains("samples_passed"));
        EXPECT_EQ(d["hiz_unsafe"], false);
    }
}

// Off, or without the prepass: no hiz pass, no level image, no verdicts; on, the final image
// is unchanged.
TEST_F(Hiz, OffAddsNothingAndOnLeavesTheImageAlone) {
    const FrameResult off = render("atrium", {"count_draws=on"}, 160, 90, ReadBack::Yes);
    const FrameResult on = render("atrium", {"count_draws=on", "hiz=on"}, 160, 90, ReadBack::Yes);
    EXPECT_FALSE((off.find<HizResult>() != nullptr));
    for (const PassResult& p : off.passes) EXPECT_NE(p.name.rfind("hiz", 0), 0u) << p.name;
    for (const ResourceSummary& r : off.resources) EXPECT_NE(r.name.rfind("hiz.", 0), 0u);
    for (const DrawReport& d : passes::draws_of(off).draws) EXPECT_FALSE(d.hiz.has_value());
    EXPECT_EQ(off.rgba8, on.rgba8);
    std::vector<std::string> on_passes;
    for (const PassResult& p : on.passes)
        if (p.name.rfind("hiz", 0) == 0) on_passes.push_back(p.name);
    EXPECT_EQ(on_passes, (std::vector<std::string>{"hiz", "hiz_test"}));
    const FrameResult no_prepass =
        render("atrium", {"hiz=on", "prepass=off"}, 160, 90, ReadBack::No);
    EXPECT_FALSE((no_prepass.find<HizResult>() != nullptr));
    EXPECT_NE(std::find(no_prepass.skipped.begin(), no_prepass.skipped.end(),
                        "hiz: skipped (prepass off)"),
              no_prepass.skipped.end());
}

}  // namespace
