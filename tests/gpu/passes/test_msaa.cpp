// msaa (issue 4) through the Renderer facade with validation on (synchronization included):
// multisampled depth, normals, roughness and HDR colour resolved inline; depth resolved to the
// nearest sample (natively or by the shader resolve); the sample count switched at run time.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "renderer/common/error.h"
#include "renderer/renderer.h"
#include "renderer/scene/loader.h"
#include "renderer/vk/capabilities.h"
#include "tests/gpu/passes/shared_renderer.h"

namespace {

using namespace ds;
using test::differing_pixels;
using test::names;

constexpr uint32_t kMsaaWidth = 240, kMsaaHeight = 135;

class Msaa : public test::SharedRenderer {
  protected:
    static void SetUpTestSuite() {
        guarded([] {
            create_renderer();
            edges_ = new scene::Scene(scene::load_scene("edges", Settings{}));
            atrium_ = new scene::Scene(scene::load_scene("atrium", Settings{}));
        });
    }
    static void TearDownTestSuite() {
        delete edges_;
        delete atrium_;
        edges_ = atrium_ = nullptr;
        current_ = nullptr;
        SharedRenderer::TearDownTestSuite();
    }

    static FrameResult render(const scene::Scene& scene,
                              const std::vector<std::string>& assignments,
                              ReadBack read_back = ReadBack::Yes, uint32_t w = kMsaaWidth,
                              uint32_t h = kMsaaHeight) {
        const Settings s = test::settings_of(assignments);
        if (current_ != &scene) {
            renderer_->set_scene(scene);
            current_ = &scene;
        }
        return renderer_->render(scene.camera, s,
                                 {.width = w, .height = h, .read_back = read_back});
    }
    // What the report must say about the depth resolve on this device.
    static std::string expected_resolve(bool reverse_z) {
        const VkResolveModeFlags modes = renderer_->device_report().depth_resolve_modes;
        if (reverse_z) return (modes & VK_RESOLVE_MODE_MAX_BIT) ? "native-max" : "shader";
        return (modes & VK_RESOLVE_MODE_MIN_BIT) ? "native-min" : "shader";
    }

    static scene::Scene* edges_;
    static scene::Scene* atrium_;
    static const scene::Scene* current_;
};

scene::Scene* Msaa::edges_ = nullptr;
scene::Scene* Msaa::atrium_ = nullptr;
const scene::Scene* Msaa::current_ = nullptr;

// Pixels whose colour is not one of the `dominant` most frequent colours of the image: on a
// scene of dark rods on a bright backdrop, mostly the blended colours along silhouettes.
size_t intermediate_pixels(const FrameResult& f, size_t dominant) {
    std::map<uint32_t, size_t> histogram;
    for (size_t i = 0; i + 3 < f.rgba8.size(); i += 4)
        ++histogram[uint32_t(f.rgba8[i]) | uint32_t(f.rgba8[i + 1]) << 8 |
                    uint32_t(f.rgba8[i + 2]) << 16];
    std::vector<size_t> counts;
    for (const auto& [colour, n] : histogram) counts.push_back(n);
    std::sort(counts.rbegin(), counts.rend());
    size_t top = 0;
    for (size_t i = 0; i < std::min(dominant, counts.size()); ++i) top += counts[i];
    return f.rgba8.size() / 4 - top;
}

size_t distinct_colours(const FrameResult& f) {
    std::map<uint32_t, size_t> histogram;
    for (size_t i = 0; i + 3 < f.rgba8.size(); i += 4)
        ++histogram[uint32_t(f.rgba8[i]) | uint32_t(f.rgba8[i + 1]) << 8 |
                    uint32_t(f.rgba8[i + 2]) << 16];
    return histogram.size();
}

// edges and atrium at 4x, and 1 -> 4 -> 1 in one Renderer: validation-clean, the same ten
// passes, the report's msaa fields, and the 1x frame after 4x like the one before.
TEST_F(Msaa, FourSamplesAndSwitchingAreValidationClean) {
    for (const scene::Scene* scene : {edges_, atrium_}) {
        SCOPED_TRACE(scene == edges_ ? "edges" : "atrium");
        const FrameResult one = render(*scene, {});
        const FrameResult four = render(*scene, {"msaa=4"});
        const FrameResult again = render(*scene, {});
        EXPECT_EQ(one.msaa.samples, 1u);
        EXPECT_EQ(one.msaa.depth_resolve, "");
        EXPECT_FALSE(one.msaa.edge_pixels);
        EXPECT_EQ(four.msaa.samples, 4u);
        EXPECT_EQ(four.msaa.depth_resolve, expected_resolve(/*reverse_z=*/true));
        ASSERT_TRUE(four.msaa.edge_pixels);
        EXPECT_GT(*four.msaa.edge_pixels, 0u);
        EXPECT_LT(*four.msaa.edge_pixels, uint64_t(kMsaaWidth) * kMsaaHeight);
        // msaa adds no pass of its own but the shader depth resolve where the device has no
        // native nearest-sample resolve (lavapipe).
        std::vector<std::string> expected = names(one);
        if (four.msaa.depth_resolve == "shader")
            expected.insert(expected.begin() + 2, "depth_resolve");
        EXPECT_EQ(names(four), expected);
        EXPECT_LT(differing_pixels(one, again, 8), size_t(kMsaaWidth) * kMsaaHeight / 100);
        EXPECT_EQ(renderer_->validation_message_count(), 0u);
    }
}

// The structural switches that change what touches the multisampled images, at 4x.
TEST_F(Msaa, StructuralCombinationsAtFourSamples) {
    for (const char* prepass : {"on", "off"})
        for (const char* reverse : {"on", "off"})
            for (const char* count : {"on", "off"}) {
                const std::vector<std::string> s = {"msaa=4", std::string("prepass=") + prepass,
                                                    std::string("reverse_z=") + reverse,
                                                    std::string("count_fragments=") + count};
                SCOPED_TRACE(s[1] + " " + s[2] + " " + s[3]);
                const FrameResult f = render(*atrium_, s, ReadBack::Yes, 160, 90);
                EXPECT_EQ(f.msaa.depth_resolve, expected_resolve(std::string(reverse) == "on"));
                ASSERT_TRUE(f.covered_pixels);
                EXPECT_GT(*f.covered_pixels, 0u);
                EXPECT_EQ(renderer_->validation_message_count(), 0u);
            }
}

// Dark rods and wires on a bright backdrop: at 4x their silhouettes blend, so far more
// pixels hold neither the backdrop's nor a rod's colour.
TEST_F(Msaa, MoreIntermediateColoursAlongSilhouettes) {
    const std::vector<std::string> common = {"gtao=off", "contact_shadows=off", "shadows=off"};
    auto with = [&](const char* msaa) {
        std::vector<std::string> s = common;
        s.push_back(msaa);
        return render(*edges_, s, ReadBack::Yes, 320, 180);
    };
    const FrameResult one = with("msaa=1");
    const FrameResult four = with("msaa=4");
    const size_t mid1 = intermediate_pixels(one, 8), mid4 = intermediate_pixels(four, 8);
    const size_t colours1 = distinct_colours(one), colours4 = distinct_colours(four);
    std::printf(
        "edges: intermediate pixels 1x %zu, 4x %zu; distinct colours 1x %zu, 4x %zu; "
        "edge pixels 4x %llu\n",
        mid1, mid4, colours1, colours4, (unsigned long long)four.msaa.edge_pixels.value_or(0));
    EXPECT_GT(double(mid4), 1.2 * double(mid1));
    EXPECT_GT(colours4, colours1);
}

// Every resolved depth texel holds the nearest of its pixel's samples: the largest with
// reverse-Z, the smallest otherwise (never sample zero's or an average). Silhouettes against
// the sky (far and covered samples in one pixel; the atrium has sky) are edge pixels.
TEST_F(Msaa, ResolvedDepthIsTheNearestSample) {
    size_t all_sky_silhouettes = 0;
    for (const scene::Scene* scene : {edges_, atrium_})
        for (const bool reverse : {true, false}) {
            SCOPED_TRACE(std::string(scene == edges_ ? "edges " : "atrium ") +
                         (reverse ? "reverse_z=on" : "reverse_z=off"));
            const FrameResult f =
                render(*scene, {"msaa=4", reverse ? "reverse_z=on" : "reverse_z=off"},
                       ReadBack::WithMsaaDepth);
            const size_t pixels = size_t(f.width) * f.height;
            if (f.msaa.resolved_depth.empty()) GTEST_SKIP() << "depth format is not D32";
            ASSERT_EQ(f.msaa.resolved_depth.size(), pixels);
            ASSERT_EQ(f.msaa.depth_samples.size(), pixels * 4);
            const float far = reverse ? 0.0f : 1.0f;
            size_t wrong = 0, not_sample_zero = 0, sky_silhouettes = 0;
            for (size_t p = 0; p < pixels; ++p) {
                const float* s = &f.msaa.depth_samples[p * 4];
                float nearest = s[0];
                size_t far_samples = 0;
                for (size_t i = 0; i < 4; ++i) {
                    nearest = reverse ? std::max(nearest, s[i]) : std::min(nearest, s[i]);
                    far_samples += s[i] == far;
                }
                wrong += f.msaa.resolved_depth[p] != nearest;
                not_sample_zero += nearest != s[0];
                sky_silhouettes += far_samples > 0 && far_samples < 4;
            }
            std::printf(
                "%s: %zu pixels whose nearest sample is not sample 0, %zu sky silhouettes, "
                "%llu edge pixels\n",
                reverse ? "reverse-Z" : "forward-Z", not_sample_zero, sky_silhouettes,
                (unsigned long long)f.msaa.edge_pixels.value_or(0));
            EXPECT_EQ(wrong, 0u);
            EXPECT_GT(not_sample_zero, 0u) << "the scene must tell MAX from SAMPLE_ZERO";
            ASSERT_TRUE(f.msaa.edge_pixels);
            EXPECT_GE(*f.msaa.edge_pixels, sky_silhouettes);
            all_sky_silhouettes += sky_silhouettes;
        }
    EXPECT_GT(all_sky_silhouettes, 0u);
}

TEST_F(Msaa, UnsupportedCountIsAClearError) {
    const VkSampleCountFlags supported = renderer_->device_report().color_sample_counts &
                                         renderer_->device_report().depth_sample_counts;
    if (supported & VK_SAMPLE_COUNT_8_BIT) GTEST_SKIP() << "the device supports 8 samples";
    try {
        render(*edges_, {"msaa=8"});
        ADD_FAILURE() << "msaa=8 must throw";
    } catch (const ds::Error& e) {
        EXPECT_NE(std::string(e.what()).find("supports sample counts"), std::string::npos)
            << e.what();
    }
    Settings s;
    // Not a sample count at all: the registry refuses it (a usage error), before any frame.
    EXPECT_THROW(s.set("msaa", "3"), ds::UsageError);
}

}  // namespace
