#pragma once
// Shared by the screen-space pass tests: a fixture that fails a test on any validation message
// it caused, the four passes wired in frame order, and pixel-selection helpers.
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "renderer/passes/ao_spatial.h"
#include "renderer/passes/ao_temporal.h"
#include "renderer/passes/contact_shadows.h"
#include "renderer/passes/gtao.h"
#include "tests/gpu/screen_space/gpu_rig.h"

namespace ds::test {

class ScreenSpaceTest : public ::testing::Test {
  protected:
    void SetUp() override { baseline_ = rig().context().validation_message_count(); }
    void TearDown() override {
        EXPECT_EQ(rig().context().validation_message_count(), baseline_)
            << "validation messages (printed above)";
    }
    static GpuRig& rig() { return GpuRig::get(); }

  private:
    uint64_t baseline_ = 0;
};

// The four passes in the renderer's order: gtao -> ao_spatial -> ao_temporal ->
// contact_shadows.
struct ScreenSpacePasses {
    passes::GtaoPass gtao;
    passes::AoSpatialPass spatial;
    passes::AoTemporalPass temporal;
    passes::ContactShadowsPass contact;

    explicit ScreenSpacePasses(const passes::PassServices& services, float gtao_scale = 0.5f,
                               uint32_t gtao_slices = passes::GtaoPass::kSlices,
                               uint32_t gtao_steps = passes::GtaoPass::kSteps)
        : gtao(services, gtao_scale, gtao_slices, gtao_steps),
          spatial(services),
          temporal(services),
          contact(services) {}

    GpuRig::Declare declare() {
        return [this](graph::RenderGraph& g, const passes::FrameInputs& in,
                      passes::FrameResources& res) {
            gtao.add(g, in, res);
            spatial.add(g, in, res);
            temporal.add(g, in, res);
            contact.add(g, in, res);
        };
    }
};

// Every pixel (x, y) of `frame` for which `keep` holds.
inline std::vector<glm::ivec2> select_pixels(const SyntheticFrame& frame,
                                             const std::function<bool(const PixelHit&)>& keep) {
    std::vector<glm::ivec2> out;
    for (uint32_t y = 0; y < frame.height; ++y)
        for (uint32_t x = 0; x < frame.width; ++x)
            if (keep(frame.hit(x, y))) out.push_back({int(x), int(y)});
    return out;
}

// Whether every pixel within `radius` (Chebyshev) of p is inside and shows `surface`.
inline bool neighbourhood_is(const SyntheticFrame& frame, glm::ivec2 p, int radius,
                             Surface surface) {
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
            const int x = p.x + dx, y = p.y + dy;
            if (x < 0 || y < 0 || x >= int(frame.width) || y >= int(frame.height)) return false;
            if (frame.hit(uint32_t(x), uint32_t(y)).surface != surface) return false;
        }
    return true;
}

inline std::string png_path(const std::string& name) {
    return "/tmp/depthscope_ss_" + name + ".png";
}

}  // namespace ds::test
