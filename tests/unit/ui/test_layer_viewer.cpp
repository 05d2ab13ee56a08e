// The read-only inspector of a layer capture (ui/layer_viewer.h) on a capture made here in
// memory: the selected pass's count image fitted right of the column, its heat map, the
// hovered pixel's three counts. No device: ImGui frames without a backend.
#include <gtest/gtest.h>

#include <imgui.h>

#include "ui/layer_viewer.h"

namespace ds::ui {
namespace {

capture::LayerCaptureData two_by_two() {
    capture::LayerCaptureData data;
    data.report = {{"source", "layer"},
                   {"application", "test"},
                   {"frame", 3},
                   {"passes", {{{"index", 0}, {"name", "prepass"}}}},
                   {"draws",
                    {{{"pass", 0},
                      {"name", "wall"},
                      {"shaded", 3},
                      {"discarded", 1},
                      {"rasterized", 4},
                      {"samples_passed", 3}}}},
                   {"not_analysed", nlohmann::json::array()}};
    capture::LayerPassImages p;
    p.name = "prepass";
    p.width = 2;
    p.height = 2;
    p.counts = {std::vector<uint32_t>{0, 1, 2, 0}, std::vector<uint32_t>{0, 0, 1, 0},
                std::vector<uint32_t>{1, 1, 2, 0}};
    p.max = {2, 1, 2};
    data.images.push_back(p);
    return data;
}

class LayerViewerTest : public testing::Test {
  protected:
    void SetUp() override {
        context_ = ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.DisplaySize = {1060, 600};
        io.IniFilename = nullptr;
        unsigned char* pixels = nullptr;
        int w = 0, h = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    }
    void TearDown() override { ImGui::DestroyContext(context_); }
    void frame(LayerViewer& viewer, ImVec2 mouse) {
        ImGui::GetIO().MousePos = mouse;
        ImGui::NewFrame();
        viewer.draw({1060, 600});
        ImGui::Render();
    }
    ImGuiContext* context_ = nullptr;
};

TEST_F(LayerViewerTest, FitsThePassImageBesideTheColumnAndReadsTheHoveredPixel) {
    LayerViewer viewer(two_by_two());
    frame(viewer, {-1, -1});
    const ViewerBlit& blit = viewer.blit();
    ASSERT_NE(blit.rgba8, nullptr);
    EXPECT_EQ(blit.width, 2u);
    // 600 wide right of the 460-pixel column, 600 high: a 600 x 600 square.
    EXPECT_FLOAT_EQ(blit.dst_w, 600.0f);
    EXPECT_FLOAT_EQ(blit.dst_x, 460.0f);
    // Shaded heat map: 0 is black, the largest count (2) white.
    EXPECT_EQ((*blit.rgba8)[0], 0);
    EXPECT_EQ((*blit.rgba8)[2 * 4], 255);
    EXPECT_TRUE(viewer.readout().empty());
    // Bottom-left pixel (0, 1): shaded 2, discarded 1, rasterized 2; twice for ImGui's hover.
    frame(viewer, {460 + 150, 450});
    frame(viewer, {460 + 150, 450});
    EXPECT_EQ(viewer.readout(), "0, 1: shaded 2, discarded 1, rasterized 2");
    // The rasterized image: pixel (1, 0) holds 1 of 2.
    viewer.select(0, 2);
    frame(viewer, {-1, -1});
    EXPECT_GT((*viewer.blit().rgba8)[1 * 4 + 2], 0);
}

// With the depth checks on: the Z-fight competitors and EQUAL marks are two more images, the
// readout says them, and a pass without them falls back to shaded.
TEST_F(LayerViewerTest, ShowsTheZfightAndEqualImagesWhereThePassHasThem) {
    capture::LayerCaptureData data = two_by_two();
    data.report["zfight"] = {{"steps", 4}, {"pixels", 1}, {"pairs", nlohmann::json::array()}};
    data.report["equal_check"] = {{"holes", 1}, {"multiple", 1}};
    data.images[0].counts[3] = {0, 0, 1, 0};
    data.images[0].max[3] = 1;
    data.images[0].counts[4] = {1, 0, 2, 0};
    data.images[0].max[4] = 2;
    data.images.push_back(data.images[0]);
    data.images[1].counts[3].clear();
    data.images[1].counts[4].clear();
    LayerViewer viewer(std::move(data));
    viewer.select(0, 4);
    frame(viewer, {-1, -1});
    // Pixel 0 a hole (magenta), pixel 2 a tie (yellow), pixel 1 nothing (transparent).
    const std::vector<uint8_t>& rgba = *viewer.blit().rgba8;
    EXPECT_EQ(rgba[0], 255);
    EXPECT_EQ(rgba[2], 255);
    EXPECT_EQ(rgba[2 * 4 + 1], 230);
    EXPECT_EQ(rgba[1 * 4 + 3], 0);
    frame(viewer, {460 + 150, 450});
    frame(viewer, {460 + 150, 450});
    EXPECT_EQ(viewer.readout(),
              "0, 1: shaded 2, discarded 1, rasterized 2, competing 1, EQUAL tie");
    viewer.select(1, 3);  // the second pass has no Z-fight image: shaded instead
    frame(viewer, {-1, -1});
    EXPECT_EQ((*viewer.blit().rgba8)[2 * 4], 255);
}

}  // namespace
}  // namespace ds::ui
