// Seed 004's fix, through the Renderer facade with validation on: the decals scene's coplanar
// overlays Z-fight with their bases and are shaded twice under EQUAL when drawn like any
// surface (decal_pass=off); the decals pass draws each once, visible in its own colour, with no
// Z-fight and no tie left (decal_pass=on), in every structural configuration.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "renderer/frame/frame_uniforms.h"
#include "renderer/passes/equal_check.h"
#include "renderer/passes/zfight.h"
#include "renderer/renderer.h"
#include "renderer/scene/builtin/scene_facts.h"
#include "tests/gpu/passes/shared_renderer.h"

namespace {

using namespace ds;
namespace facts = scene::builtin::facts;

constexpr uint32_t kDecalsWidth = 640, kDecalsHeight = 360;

class Decals : public test::SharedScene {
  protected:
    static void SetUpTestSuite() { set_up_with("decals"); }

    static FrameResult render(const std::vector<std::string>& settings,
                              const InspectRequest& inspect = {}) {
        return renderer_->render(scene_->camera, test::settings_of(settings),
                                 {.width = kDecalsWidth,
                                  .height = kDecalsHeight,
                                  .read_back = ReadBack::Yes,
                                  .inspect = {inspect}});
    }
    // The pixel a world point lands on (the renderer's projection; either direction).
    static glm::ivec2 pixel_of(const glm::vec3& world) {
        const scene::Camera& c = scene_->camera;
        const glm::mat4 vp =
            perspective(c.yfov, float(kDecalsWidth) / kDecalsHeight, c.znear, c.zfar, true) *
            c.view();
        const glm::vec4 clip = vp * glm::vec4(world, 1.0f);
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        return {int((ndc.x * 0.5f + 0.5f) * kDecalsWidth),
                int((ndc.y * 0.5f + 0.5f) * kDecalsHeight)};
    }
    // A point of overlay o at (s, t) of its rectangle.
    static glm::vec3 at(const facts::DecalsOverlay& o, float s, float t) {
        const facts::DecalsRect r = facts::decals_overlay_rect(o);
        return r.origin + r.edge_u * s + r.edge_v * t;
    }
};

glm::vec3 colour_at(const FrameResult& f, glm::ivec2 p) {
    const size_t i = (size_t(p.y) * f.width + size_t(p.x)) * 4;
    return {f.rgba8[i] / 255.0f, f.rgba8[i + 1] / 255.0f, f.rgba8[i + 2] / 255.0f};
}

// The overlay's hue dominates: each channel the colour has clearly above each it lacks. The
// BLEND overlay is half blue over grey: blue leads by less.
bool looks_like(glm::vec3 seen, const facts::DecalsOverlay& o) {
    const float lead = o.alpha == facts::DecalsAlpha::Blend ? 1.15f : 1.5f;
    float weakest_lit = 1e9f, strongest_unlit = 0.0f;
    for (int c = 0; c < 3; ++c) {
        if (o.colour[c] > 0.5f)
            weakest_lit = std::min(weakest_lit, seen[c]);
        else
            strongest_unlit = std::max(strongest_unlit, seen[c]);
    }
    return weakest_lit > lead * strongest_unlit + 0.02f;
}

bool looks_grey(glm::vec3 seen) {
    const float hi = std::max({seen.r, seen.g, seen.b}), lo = std::min({seen.r, seen.g, seen.b});
    return hi - lo < 0.12f * hi + 0.02f;
}

bool is_overlay(const std::string& node) {
    return std::any_of(std::begin(facts::kDecalsOverlays), std::end(facts::kDecalsOverlays),
                       [&](const facts::DecalsOverlay& o) { return node == o.node; });
}

TEST_F(Decals, WithoutTheDecalPassOverlaysFightTheirBasesAndTieUnderEqual) {
    const FrameResult f = render({"decal_pass=off", "zfight=on", "equal_check=on"});
    ASSERT_TRUE(f.find<ZfightResult>());
    ASSERT_TRUE(f.find<EqualCheckResult>());
    EXPECT_GT(f.find<EqualCheckResult>()->multiple, 0u);
    for (const std::string& n : test::names(f)) EXPECT_NE(n, "decals");
    for (const facts::DecalsOverlay& o : facts::kDecalsOverlays) {
        if (o.alpha == facts::DecalsAlpha::Blend) continue;  // BLEND is never in the prepass
        const std::string base = facts::kDecalsSurfaces[o.surface].node;
        EXPECT_TRUE(std::any_of(f.find<ZfightResult>()->pairs.begin(),
                                f.find<ZfightResult>()->pairs.end(),
                                [&](const ZfightPair& p) {
                                    return (p.a.node == o.node && p.b.node == base) ||
                                           (p.a.node == base && p.b.node == o.node);
                                }))
            << o.node << " on " << base;
    }
}

TEST_F(Decals, TheDecalPassLeavesNoFightAndNoTie) {
    const FrameResult f = render({"zfight=on", "equal_check=on"});
    ASSERT_TRUE(f.find<ZfightResult>());
    ASSERT_TRUE(f.find<EqualCheckResult>());
    EXPECT_EQ(f.find<ZfightResult>()->pixels, 0u);
    for (const ZfightPair& p : f.find<ZfightResult>()->pairs)
        EXPECT_FALSE(is_overlay(p.a.node) || is_overlay(p.b.node)) << p.a.node << " " << p.b.node;
    EXPECT_EQ(f.find<EqualCheckResult>()->multiple, 0u);
    EXPECT_EQ(f.find<EqualCheckResult>()->holes, 0u);
    const std::vector<std::string> n = test::names(f);
    const auto forward = std::find(n.begin(), n.end(), "forward");
    const auto decals = std::find(n.begin(), n.end(), "decals");
    ASSERT_NE(decals, n.end());
    EXPECT_LT(forward, decals) << "after forward";
}

// Every pixel the decals pass shades, it shades once; it shades the overlays' area (the MASK
// overlays' surviving part only), which forward no longer shades twice.
TEST_F(Decals, EachOverlayPixelIsShadedOnce) {
    const FrameResult f = render({"count_fragments=on"}, {"decal_counts", 0});
    ASSERT_TRUE(f.inspected);
    uint64_t once = 0;
    for (size_t i = 0; i < f.inspected->texels.size(); i += 4) {
        EXPECT_LE(f.inspected->texels[i], 1.0f) << "texel " << i / 4;
        once += f.inspected->texels[i] == 1.0f;
    }
    auto pass = std::find_if(f.passes.begin(), f.passes.end(),
                             [](const PassResult& p) { return p.name == "decals"; });
    ASSERT_NE(pass, f.passes.end());
    EXPECT_EQ(pass->shaded_fragments, once);
    EXPECT_GT(once, 1000u);
}

// Inside each overlay (a margin from its edges) the frame has the overlay's hue; a MASK
// overlay's cut-away part shows the grey base. In every structural configuration.
TEST_F(Decals, EachOverlayIsVisibleInItsOwnColour) {
    for (const char* extra : {"msaa=1", "msaa=4", "prepass=off", "reverse_z=off",
                              "depth_format=d16", "depth_compare=greater_or_equal"}) {
        SCOPED_TRACE(extra);
        const FrameResult f = render({extra});
        ASSERT_EQ(f.rgba8.size(), size_t(kDecalsWidth) * kDecalsHeight * 4);
        for (const facts::DecalsOverlay& o : facts::kDecalsOverlays) {
            const bool mask = o.alpha == facts::DecalsAlpha::Mask;
            const float keep = mask ? facts::kDecalsMaskKeep : 1.0f;
            for (float t : {0.25f, 0.5f, 0.75f}) {
                for (float s : {0.1f, 0.5f, 0.9f}) {
                    const glm::vec3 seen = colour_at(f, pixel_of(at(o, s * keep, t)));
                    EXPECT_TRUE(looks_like(seen, o))
                        << o.node << " at " << s * keep << "," << t << ": " << seen.r << " "
                        << seen.g << " " << seen.b;
                }
                if (!mask) continue;
                const glm::vec3 cut = colour_at(f, pixel_of(at(o, 0.5f + 0.5f * keep, t)));
                EXPECT_TRUE(looks_grey(cut))
                    << o.node << " cut away: " << cut.r << " " << cut.g << " " << cut.b;
            }
        }
    }
}

}  // namespace
