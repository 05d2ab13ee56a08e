// Depth knobs (issue 10 part 3) through the Renderer facade with validation on: depth_format
// (each format the device has) x reverse_z x prepass x msaa keeps the frame's contracts;
// znear / zfar reach the projection, the report's facts and the inspected depth's planes.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "renderer/common/error.h"
#include "renderer/format/format.h"
#include "renderer/passes/frame.h"
#include "renderer/renderer.h"
#include "renderer/scene/loader.h"
#include "renderer/view/readout.h"
#include "renderer/vk/capabilities.h"
#include "tests/gpu/passes/shared_renderer.h"

namespace {

using namespace ds;
using passes::DepthChoice;
using test::differing_pixels;

constexpr uint32_t kWidth = 160, kHeight = 90;
constexpr const char* kFormats[] = {"d32f", "d24", "d16"};

DepthChoice choice_of(const std::string& name) {
    for (DepthChoice c : {DepthChoice::D32f, DepthChoice::D24, DepthChoice::D16})
        if (name == passes::depth_choice_name(c)) return c;
    ADD_FAILURE() << name;
    return DepthChoice::D32f;
}

std::string usage_error(DepthChoice choice, const std::vector<VkFormat>& supported) {
    try {
        passes::resolve_depth_format(choice, supported, "gpu");
    } catch (const UsageError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no UsageError for " << passes::depth_choice_name(choice);
    return "";
}

// Each choice takes the first of its formats the device has; none is one clear error.
TEST(DepthFormatChoice, ResolvesAgainstTheDevicesFormats) {
    using passes::resolve_depth_format;
    const std::vector<VkFormat> all(std::begin(vk::kDepthFormatCandidates),
                                    std::end(vk::kDepthFormatCandidates));
    EXPECT_EQ(resolve_depth_format(DepthChoice::D32f, all, "gpu"), VK_FORMAT_D32_SFLOAT);
    EXPECT_EQ(resolve_depth_format(DepthChoice::D24, all, "gpu"), VK_FORMAT_D24_UNORM_S8_UINT);
    EXPECT_EQ(resolve_depth_format(DepthChoice::D16, all, "gpu"), VK_FORMAT_D16_UNORM);
    const std::vector<VkFormat> x8 = {VK_FORMAT_X8_D24_UNORM_PACK32, VK_FORMAT_D32_SFLOAT_S8_UINT};
    EXPECT_EQ(resolve_depth_format(DepthChoice::D24, x8, "gpu"), VK_FORMAT_X8_D24_UNORM_PACK32);
    EXPECT_EQ(resolve_depth_format(DepthChoice::D32f, x8, "gpu"), VK_FORMAT_D32_SFLOAT_S8_UINT);

    const std::string e =
        usage_error(DepthChoice::D24, {VK_FORMAT_D32_SFLOAT, VK_FORMAT_D16_UNORM});
    EXPECT_NE(e.find("depth_format=d24: gpu"), std::string::npos) << e;
    EXPECT_NE(e.find("supported: d32f (D32_SFLOAT), d16 (D16_UNORM)"), std::string::npos) << e;
    EXPECT_NE(usage_error(DepthChoice::D16, {}).find("supported: none"), std::string::npos);
}

// The knobs replace the scene camera's planes; the planes as combined must be 0 < near < far.
TEST(DepthPlanes, EffectiveCameraAndItsErrors) {
    scene::Camera scene_camera;
    scene_camera.znear = 0.1f;
    scene_camera.zfar = 200.0f;
    passes::FrameOptions o;
    EXPECT_EQ(passes::effective_camera(scene_camera, o).znear, 0.1f);
    o.znear = 0.5f;
    o.zfar = 50.0f;
    const scene::Camera c = passes::effective_camera(scene_camera, o);
    EXPECT_EQ(c.znear, 0.5f);
    EXPECT_EQ(c.zfar, 50.0f);
    EXPECT_EQ(c.position, scene_camera.position);

    auto error = [&](std::optional<float> znear, std::optional<float> zfar) -> std::string {
        passes::FrameOptions bad;
        bad.znear = znear;
        bad.zfar = zfar;
        try {
            passes::effective_camera(scene_camera, bad);
        } catch (const UsageError& e) {
            return e.what();
        }
        return "(no error)";
    };
    EXPECT_EQ(error(0.0f, std::nullopt), "znear=0: the near plane must be above 0");
    EXPECT_EQ(error(300.0f, std::nullopt), "znear=300 must be below zfar=200 (the scene camera's)");
    EXPECT_EQ(error(std::nullopt, 0.05f), "znear=0.1 (the scene camera's) must be below zfar=0.05");
    EXPECT_EQ(error(5.0f, 5.0f), "znear=5 must be below zfar=5");
}

// One validated renderer on the atrium for every test.
class DepthKnobs : public test::SharedScene {
  public:
    static uint64_t shaded(const FrameResult& f, const std::string& pass) {
        for (const PassResult& p : f.passes)
            if (p.name == pass && p.shaded_fragments) return *p.shaded_fragments;
        ADD_FAILURE() << pass << " has no shaded_fragments";
        return 0;
    }

  protected:
    static void SetUpTestSuite() { set_up_with("atrium"); }
    static FrameResult render(const std::vector<std::string>& assignments,
                              const InspectRequest& inspect = {}) {
        return renderer_->render(
            scene_->camera, test::settings_of(assignments),
            {.width = kWidth, .height = kHeight, .read_back = ReadBack::Yes, .inspect = {inspect}});
    }
    // The format the device gives `name`; none when it has none (the combination is skipped).
    static std::optional<VkFormat> device_format(const std::string& name) {
        try {
            return passes::resolve_depth_format(choice_of(name),
                                                renderer_->device_report().depth_formats, "device");
        } catch (const UsageError&) {
            return std::nullopt;
        }
    }
};

// One frame of the combination test and what the earlier frames fixed.
struct Combination {
    std::string format, reverse, msaa, prepass;
    VkFormat vk_format = VK_FORMAT_UNDEFINED;
};
struct Seen {
    std::map<std::string, uint64_t> covered;  // by msaa: the first frame's
    std::map<std::string, uint64_t> decals;   // by format, reverse_z, msaa: the first's
};

void expect_contracts(const Combination& c, const FrameResult& f, Seen& seen) {
    ASSERT_TRUE(f.depth);
    EXPECT_EQ(f.depth->format, c.vk_format);
    EXPECT_EQ(f.depth->reverse_z, c.reverse == "on");
    for (const ResourceSummary& r : f.resources) {
        if (r.name == "depth" || r.name == "msaa_depth") {
            EXPECT_EQ(r.format, c.vk_format) << r.name;
        }
    }
    ASSERT_TRUE(f.covered_pixels);
    const double covered = double(seen.covered.emplace(c.msaa, *f.covered_pixels).first->second);
    EXPECT_EQ(double(*f.covered_pixels), covered);
    const double fwd = double(DepthKnobs::shaded(f, "forward"));
    if (c.prepass == "on") {
        EXPECT_GE(fwd, 0.98 * covered) << "EQUAL rejected visible fragments";
        // At 4x an edge pixel shades once for each surface it shows.
        if (c.msaa == "1") {
            EXPECT_LE(fwd, 1.02 * covered);
        }
    } else {
        EXPECT_GE(fwd, 2.0 * covered) << "the authored order's overdraw";
    }
    // The atrium's BLEND surfaces are decals, drawn by the decals pass.
    const uint64_t decals = DepthKnobs::shaded(f, "decals");
    EXPECT_GT(decals, 0u);
    EXPECT_EQ(decals, seen.decals.emplace(c.format + c.reverse + c.msaa, decals).first->second);
}

// Every format x reverse_z x prepass x msaa 1/4 is validation clean (TearDown) and keeps the
// contracts: the format in use, the same covered pixels (sky and transparent leave depth
// alone), forward with the prepass and EQUAL shading each covered pixel once at 1x,
// the decals pass shading the same fragments with or without the prepass.
TEST_F(DepthKnobs, EveryCombinationKeepsTheContracts) {
    Seen seen;
    for (const char* format : kFormats) {
        const std::optional<VkFormat> vk_format = device_format(format);
        if (!vk_format) continue;
        for (const char* reverse : {"on", "off"})
            for (const char* msaa : {"1", "4"})
                for (const char* prepass : {"on", "off"}) {
                    const Combination c{format, reverse, msaa, prepass, *vk_format};
                    const std::vector<std::string> s = {
                        "depth_format=" + c.format, "reverse_z=" + c.reverse, "msaa=" + c.msaa,
                        "prepass=" + c.prepass, "count_fragments=on"};
                    SCOPED_TRACE(s[0] + " " + s[1] + " " + s[2] + " " + s[3]);
                    expect_contracts(c, render(s), seen);
                }
    }
    EXPECT_EQ(seen.covered.size(), 2u);
}

// Fewer depth bits change the image in few pixels (where depth-derived effects or near-equal
// depths round differently); switching back gives the d32f image again.
TEST_F(DepthKnobs, NarrowerFormatsDifferInFewPixels) {
    const std::vector<std::string> base = {"gtao=off"};  // temporal AO would carry history
    auto with = [&](const char* format) {
        std::vector<std::string> s = base;
        s.push_back(std::string("depth_format=") + format);
        return render(s);
    };
    const FrameResult d32f = with("d32f");
    const size_t total = size_t(kWidth) * kHeight;
    for (const char* format : {"d24", "d16"}) {
        if (!device_format(format)) continue;
        const FrameResult other = with(format);
        const size_t differ = differing_pixels(d32f, other, 8);
        std::printf(
            "%s: differs from d32f in %zu of %zu pixels by more than 8/255, %zu by more "
            "than 0\n",
            format, differ, total, differing_pixels(d32f, other, 0));
        EXPECT_LT(differ, total / 100) << format;
    }
    const FrameResult again = with("d32f");
    EXPECT_EQ(again.rgba8, d32f.rgba8) << "the d32f targets and pipelines come back";
}

// znear / zfar reach the report's facts and the inspected depth's planes: the stored depth
// changes, the linear depth read through those planes does not.
TEST_F(DepthKnobs, PlanesReachTheReportAndTheLinearDepthReadout) {
    const InspectRequest depth{.resource = "depth"};
    const FrameResult scene_planes = render({}, depth);
    ASSERT_TRUE(scene_planes.depth);
    EXPECT_EQ(scene_planes.depth->znear, scene_->camera.znear);
    EXPECT_EQ(scene_planes.depth->zfar, scene_->camera.zfar);
    const FrameResult set = render({"znear=0.5", "zfar=60"}, depth);
    ASSERT_TRUE(set.depth);
    EXPECT_EQ(set.depth->znear, 0.5f);
    EXPECT_EQ(set.depth->zfar, 60.0f);
    ASSERT_TRUE(scene_planes.inspected && set.inspected);
    EXPECT_EQ(set.inspected->znear, 0.5f);
    EXPECT_EQ(set.inspected->zfar, 60.0f);
    size_t compared = 0;
    for (uint32_t y = 0; y < kHeight; y += 7)
        for (uint32_t x = 0; x < kWidth; x += 7) {
            const auto a = view::readout(*scene_planes.inspected, x, y);
            const auto b = view::readout(*set.inspected, x, y);
            ASSERT_TRUE(a && b);
            if (!a->linear_depth || !b->linear_depth) continue;  // sky
            EXPECT_NE(a->raw[0], b->raw[0]) << x << "," << y;
            EXPECT_NEAR(*b->linear_depth, *a->linear_depth, 1e-3f * *a->linear_depth)
                << x << "," << y;
            ++compared;
        }
    EXPECT_GT(compared, 100u);
}

// Refusals come before the frame: the renderer keeps working with good settings after them.
TEST_F(DepthKnobs, BadPlanesAreUsageErrors) {
    EXPECT_THROW(render({"znear=0"}), UsageError);
    EXPECT_THROW(render({"znear=500"}), UsageError);  // the atrium's zfar is 200
    EXPECT_THROW(render({"znear=2", "zfar=1"}), UsageError);
    const FrameResult f = render({"zfar=150"});
    ASSERT_TRUE(f.depth);
    EXPECT_EQ(f.depth->zfar, 150.0f);
}

}  // namespace
