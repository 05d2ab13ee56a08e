// render_path=subpass (issue 15, seed 002) through the Renderer facade with validation on (the
// fixture fails any test that leaves a validation message): one render pass of two subpasses,
// its image against the dynamic path's on every built-in scene, the tile budget and merge
// verdict, and what the path turns off.
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "renderer/common/error.h"
#include "renderer/renderer.h"
#include "renderer/scene/builtin/builtin.h"
#include "renderer/vk/capabilities.h"
#include "tests/gpu/passes/shared_renderer.h"

namespace {

using namespace ds;
using test::differing_pixels;

constexpr uint32_t kWidth = 320, kHeight = 180;

class RenderPath : public test::SceneSwitching {
  protected:
    FrameResult frame(const std::string& scene, std::vector<std::string> settings,
                      const InspectRequest& inspect = {}) {
        return render(scene, settings, kWidth, kHeight, ReadBack::Yes, inspect);
    }
    bool has_msaa4() const {
        const vk::DeviceReport& r = renderer_->device_report();
        return (r.color_sample_counts & r.depth_sample_counts & VK_SAMPLE_COUNT_4_BIT) != 0;
    }
};

const graph::TilerAttachment* attachment(const FrameResult& f, const std::string& name) {
    for (const graph::TilerAttachment& a : f.tiler->attachments)
        if (a.name == name) return &a;
    ADD_FAILURE() << "the render pass has no attachment " << name;
    return nullptr;
}

TEST_F(RenderPath, KnobIsValidatedAndDefaultsToDynamic) {
    EXPECT_EQ(Settings().get("render_path"), "dynamic");
    for (const char* bad : {"render_path=tiler", "render_path=", "render_path=Subpass"})
        EXPECT_THROW(test::settings_of({bad}), UsageError) << bad;
}

// The acceptance: gtao and contact_shadows off on both, < 0.1 % of pixels differ by > 8/255.
TEST_F(RenderPath, SubpassImageMatchesTheDynamicPathOnEveryBuiltInScene) {
    std::vector<int> counts = {1};
    if (has_msaa4()) counts.push_back(4);
    for (const scene::builtin::Info& info : scene::builtin::list()) {
        const std::string& scene = info.name;
        for (int msaa : counts) {
            const std::vector<std::string> common = {"gtao=off", "contact_shadows=off",
                                                     "msaa=" + std::to_string(msaa)};
            std::vector<std::string> subpass = common;
            subpass.push_back("render_path=subpass");
            const FrameResult dynamic = frame(scene, common);
            const FrameResult tiled = frame(scene, subpass);
            ASSERT_FALSE(dynamic.tiler) << scene;
            ASSERT_TRUE(tiled.tiler) << scene << ": the subpass path did not run";
            const size_t differ = differing_pixels(dynamic, tiled, 8);
            EXPECT_LT(100.0 * double(differ) / double(kWidth * kHeight), 0.1)
                << scene << " msaa " << msaa << ": " << differ << " pixels differ";
        }
    }
}

TEST_F(RenderPath, GraphShowsTwoSubpassesInputAttachmentsAndAByRegionDependency) {
    frame("atrium", {"render_path=subpass"});
    const std::string dump = renderer_->graph_dump();
    EXPECT_NE(dump.find("render pass 'gbuffer_lighting'"), std::string::npos) << dump;
    EXPECT_NE(dump.find("2 subpasses"), std::string::npos);
    EXPECT_NE(dump.find("subpass 0: depth_prepass"), std::string::npos);
    EXPECT_NE(dump.find("subpass 1: forward skybox"), std::string::npos);
    EXPECT_NE(dump.find("input normals [SHADER_READ_ONLY_OPTIMAL], roughness"), std::string::npos);
    EXPECT_NE(dump.find("dependency 0 -> 1 BY_REGION"), std::string::npos);
    EXPECT_NE(dump.find("[DEPTH_STENCIL_READ_ONLY_OPTIMAL] read-only"), std::string::npos);
}

TEST_F(RenderPath, TilerReportsTheSeedLayoutAt104BitsAndTheVerdict) {
    const FrameResult f = frame("atrium", {"render_path=subpass"});
    ASSERT_TRUE(f.tiler);
    EXPECT_EQ(f.tiler->bits_per_pixel, 104u);  // A2B10G10R10 + R8 + RGBA16F
    EXPECT_TRUE(f.tiler->fits_128);
    EXPECT_EQ(f.tiler->subpasses, 2u);
    EXPECT_EQ(f.tiler->verdict, "a tiler can merge these subpasses: yes");
    // Only the light and the depth (read after the render pass) are stored.
    ASSERT_EQ(f.tiler->attachments.front().name, "hdr");
    EXPECT_EQ(f.tiler->attachments.front().store, "store");
    for (const char* name : {"normals", "roughness"}) {
        const graph::TilerAttachment* a = attachment(f, name);
        ASSERT_TRUE(a);
        EXPECT_TRUE(a->transient) << name;
        EXPECT_EQ(a->store, "dont_care") << name;
    }
}

TEST_F(RenderPath, MsaaResolvesInTheRenderPass) {
    if (!has_msaa4()) GTEST_SKIP() << "the device has no 4x colour and depth";
    const FrameResult f = frame("edges", {"render_path=subpass", "msaa=4"});
    ASSERT_TRUE(f.tiler);
    const graph::TilerAttachment* hdr = attachment(f, "hdr");
    ASSERT_TRUE(hdr);
    EXPECT_EQ(hdr->role, "resolve");
    EXPECT_EQ(hdr->samples, 1u);
    EXPECT_EQ(f.tiler->tile_bits_per_pixel, 416u);  // 104 bits for each of 4 samples
    EXPECT_FALSE(f.tiler->fits_256);
    EXPECT_TRUE(f.tiler->mergeable) << f.tiler->verdict;
    EXPECT_EQ(attachment(f, "msaa_normals")->store, "dont_care");
}

TEST_F(RenderPath, AGbufferImageReadAfterTheRenderPassIsStored) {
    // The inspector asking for the normals is a later read: they leave tile memory.
    const FrameResult f = frame("atrium", {"render_path=subpass"}, {"normals"});
    const graph::TilerAttachment* normals = attachment(f, "normals");
    ASSERT_TRUE(normals);
    EXPECT_FALSE(normals->transient);
    EXPECT_EQ(normals->store, "store");
    ASSERT_TRUE(f.inspected);
}

TEST_F(RenderPath, ScreenSpacePassesAreOffAndSayWhy) {
    const FrameResult f = frame("atrium", {"render_path=subpass"});
    for (const char* pass : {"gtao", "contact_shadows"}) {
        const auto it = std::find_if(f.skipped.begin(), f.skipped.end(), [&](const std::string& s) {
            return s.rfind(std::string(pass) + ": skipped (render_path=subpass", 0) == 0;
        });
        EXPECT_NE(it, f.skipped.end()) << pass;
    }
}

TEST_F(RenderPath, WithoutThePrepassTheDynamicPathRuns) {
    const FrameResult f = frame("atrium", {"render_path=subpass", "prepass=off"});
    EXPECT_FALSE(f.tiler);
}

}  // namespace

namespace {

// Issue 25: the graph begins every rendering and render pass, so each combination of path,
// depth format (D24_UNORM_S8_UINT's stencil aspect included), sample count and prepass mode
// must be validation clean on a scene with everything (atrium) and one with coplanar overlays
// (decals). The fixture fails the test on any message; the trace names the combination.
TEST_F(RenderPath, EveryPathDepthFormatSampleCountAndPrepassModeIsValidationClean) {
    std::vector<int> counts = {1};
    if (has_msaa4()) counts.push_back(4);
    for (const char* scene : {"atrium", "decals"})
        for (const char* path : {"dynamic", "subpass"})
            for (const char* depth : {"d32f", "d24", "d16"})
                for (int msaa : counts)
                    for (const char* mode : {"gbuffer", "depth"}) {
                        const std::vector<std::string> settings = {
                            std::string("render_path=") + path,
                            std::string("depth_format=") + depth, "msaa=" + std::to_string(msaa),
                            std::string("prepass_mode=") + mode};
                        SCOPED_TRACE(std::string(scene) + " " + path + " " + depth + " msaa " +
                                     std::to_string(msaa) + " " + mode);
                        const FrameResult f = render(scene, settings, 160, 90, ReadBack::No);
                        EXPECT_EQ(f.tiler.has_value(), std::string(path) == "subpass");
                        ASSERT_EQ(renderer_->validation_message_count(), 0u);
                    }
}

}  // namespace
