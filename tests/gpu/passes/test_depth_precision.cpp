// depth_precision against the analytic step: the overdraw scene's front layer is a
// view-filling quad at distance 2; at the centre pixel the image's step must match, to 1 %,
// the distance between the stored depth and the next representable one of each format and
// direction, computed in double from the stored value itself.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "renderer/renderer.h"
#include "renderer/scene/loader.h"
#include "tests/gpu/passes/shared_renderer.h"

namespace {

using namespace ds;

constexpr uint32_t kPrecisionWidth = 320, kPrecisionHeight = 180;

class DepthPrecision : public test::SharedScene {
  protected:
    static void SetUpTestSuite() { set_up_with("overdraw"); }
    // The texel at the centre of `resource` (its four floats) and the frame's planes.
    static InspectedImage centre(const std::vector<std::string>& settings, const char* resource) {
        FrameResult f = renderer_->render(scene_->camera, test::settings_of(settings),
                                          {.width = kPrecisionWidth,
                                           .height = kPrecisionHeight,
                                           .read_back = ReadBack::No,
                                           .inspect = {{resource, 0}}});
        EXPECT_TRUE(f.inspected) << resource;
        return f.inspected ? *f.inspected : InspectedImage{};
    }
};

double linear(double d, bool reverse, double n, double f) {
    return reverse ? n * f / (n + d * (f - n)) : n * f / (f - d * (f - n));
}

// The stored depth's next value towards far, in the format's own steps.
double next_towards_far(double d, const std::string& format, bool reverse) {
    if (format == "d32f") return std::nextafter(float(d), reverse ? 0.0f : 1.0f);
    const double levels = format == "d24" ? 16777215.0 : 65535.0;
    return d + (reverse ? -1.0 : 1.0) / levels;
}

TEST_F(DepthPrecision, MatchesTheAnalyticStepAtTheFrontLayer) {
    const size_t centre_texel =
        (size_t(kPrecisionHeight / 2) * kPrecisionWidth + kPrecisionWidth / 2) * 4;
    for (const std::string format : {"d32f", "d24", "d16"}) {
        for (const bool reverse : {true, false}) {
            SCOPED_TRACE(format + (reverse ? " reverse-Z" : " forward-Z"));
            const std::vector<std::string> s = {"depth_precision=on", "depth_format=" + format,
                                                reverse ? "reverse_z=on" : "reverse_z=off"};
            const InspectedImage depth = centre(s, "depth");
            const InspectedImage precision = centre(s, "depth_precision");
            ASSERT_GT(depth.texels.size(), centre_texel);
            ASSERT_GT(precision.texels.size(), centre_texel);
            const double n = depth.znear, f = depth.zfar, d = depth.texels[centre_texel];
            const double z = linear(d, reverse, n, f);
            EXPECT_NEAR(z, 2.0, 0.01) << "the front layer";
            const double expected =
                std::abs(linear(next_towards_far(d, format, reverse), reverse, n, f) - z);
            const double step = precision.texels[centre_texel];
            EXPECT_NEAR(step, expected, 0.01 * expected) << "step " << step;
            EXPECT_NEAR(precision.texels[centre_texel + 1], z, 1e-3 * z) << "the ray distance";
        }
    }
}

TEST_F(DepthPrecision, OffAddsNothing) {
    const FrameResult f = renderer_->render(
        scene_->camera, test::settings_of({}),
        {.width = kPrecisionWidth, .height = kPrecisionHeight, .read_back = ReadBack::No});
    for (const ResourceSummary& r : f.resources) EXPECT_NE(r.name, "depth_precision");
}

}  // namespace
