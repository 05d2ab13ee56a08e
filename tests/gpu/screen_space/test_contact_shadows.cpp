// Contact shadows on the synthetic corner, the sun behind the wall: the floor at the wall's
// foot is shadowed, the open floor and everything farther than the ray's reach is lit.
#include <cmath>
#include <cstdio>

#include "tests/gpu/screen_space/screen_space_test.h"

namespace ds::test {
namespace {

constexpr uint32_t kContactWidth = 240, kContactHeight = 160;
const glm::vec3 kContactSun = glm::normalize(glm::vec3{1.0f, 0.6f, 0.2f});  // towards +X, 30 deg up

class ContactShadows : public ScreenSpaceTest, public ::testing::WithParamInterface<bool> {};

// contact_shadows of the uploaded frame, marched with `steps` steps.
HostImage run_contact(GpuRig& rig, uint32_t steps) {
    passes::ContactShadowsPass contact(rig.services(), steps);
    graph::RenderGraph graph(rig.context());
    return rig
        .run_frame(graph,
                   [&](graph::RenderGraph& g, const passes::FrameInputs& in,
                       passes::FrameResources& res) { contact.add(g, in, res); },
                   {"contact_shadows"})
        .images.at("contact_shadows");
}

TEST_P(ContactShadows, ShadowBehindTheWallLitElsewhere) {
    const bool reverse_z = GetParam();
    const SyntheticFrame frame = render_synthetic(corner_scene(), corner_camera(), kContactWidth,
                                                  kContactHeight, reverse_z, kContactSun);
    rig().upload(frame);
    const HostImage shadow = run_contact(rig(), passes::ContactShadowsPass::kSteps);
    write_png(png_path(std::string("contact_") + (reverse_z ? "reverse_z" : "forward_z")), shadow);

    // The floor whose ray towards the sun enters the wall within the march (0.4 m along the
    // ray: 0.34 m in x): all in shadow when the entry is well inside the reach.
    const float reach_x = passes::ContactShadowsPass::Params{}.ray_length * kContactSun.x;
    const auto foot = select_pixels(frame, [&](const PixelHit& h) {
        // Where the ray meets the wall's face (x = 0): inside the wall's extent in z and y.
        const float t = -h.position.x / kContactSun.x;
        const glm::vec3 entry = h.position + t * kContactSun;
        return h.surface == Surface::Floor && h.position.x < -0.02f &&
               h.position.x > -0.6f * reach_x && std::abs(entry.z) < kWallHalfLength - 0.2f;
    });
    ASSERT_GT(foot.size(), 50u);
    size_t checked = 0;
    for (glm::ivec2 p : foot) {
        // A ray that leaves the screen before it is well inside the wall finds nothing: skip
        // the pixels whose ray could (a screen-space limit, not a defect).
        const glm::vec3 position = frame.hit(p.x, p.y).position;
        if (!frame.pixel_of(position + (-position.x / kContactSun.x + 0.06f) * kContactSun))
            continue;
        ASSERT_EQ(shadow.at(p.x, p.y), 0.0f) << p.x << "," << p.y;
        ++checked;
    }
    EXPECT_GT(checked, 50u);

    // Open floor beyond the ray's reach from the wall, the wall's top, the sky: lit.
    const auto lit = select_pixels(frame, [&](const PixelHit& h) {
        const bool open_floor = h.surface == Surface::Floor &&
                                (h.position.x < -1.5f * reach_x || h.position.x > kWallThickness ||
                                 std::abs(h.position.z) > kWallHalfLength + 0.5f);
        const bool wall_top = h.surface == Surface::Box && h.normal.y > 0.5f;
        return open_floor || wall_top || h.surface == Surface::Sky;
    });
    ASSERT_GT(lit.size(), 10000u);
    size_t shadowed = 0;
    for (glm::ivec2 p : lit) shadowed += shadow.at(p.x, p.y) < 1.0f;
    EXPECT_EQ(shadowed, 0u);
}

// The default step count against a 64-step reference march (same ray, same jitter): at most
// 0.5 % of the pixels change between lit and occluded (the stated tolerance; the steps miss
// thin slivers of an occluder between them). Atrium: 0.40 % of 1280x720 against 16 steps.
TEST_P(ContactShadows, DefaultStepsStayWithinToleranceOfReference) {
    const SyntheticFrame frame = render_synthetic(corner_scene(), corner_camera(), kContactWidth,
                                                  kContactHeight, GetParam(), kContactSun);
    rig().upload(frame);
    const HostImage fast = run_contact(rig(), passes::ContactShadowsPass::kSteps);
    const HostImage reference = run_contact(rig(), 64);
    size_t flipped = 0, occluded = 0;
    for (size_t i = 0; i < fast.r.size(); ++i) {
        flipped += (fast.r[i] < 0.5f) != (reference.r[i] < 0.5f);
        occluded += reference.r[i] < 0.5f;
    }
    const double fraction = double(flipped) / double(fast.r.size());
    std::printf("contact shadows: %zu of %zu pixels flipped (%.3f %%), %zu occluded\n", flipped,
                fast.r.size(), 100.0 * fraction, occluded);
    EXPECT_GT(occluded, 500u);  // the comparison covers a real shadow
    EXPECT_LE(fraction, 0.005);
}

INSTANTIATE_TEST_SUITE_P(DepthConventions, ContactShadows, ::testing::Values(true, false),
                         [](const auto& info) { return info.param ? "reverse_z" : "forward_z"; });

}  // namespace
}  // namespace ds::test
