// The workspace (ui/panels/workspace.h): the panels in tabs of fixed regions beside and under
// the viewer, never over its image, every tab header clickable (real ImGui input through
// HeadlessInput), the splits dragged with the mouse and kept in imgui.ini with the open tabs.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <imgui.h>

#include "tests/unit/ui/inspector_ui.h"
#include "ui/panels/panels.h"
#include "ui/panels/workspace.h"

namespace ds::test {
namespace {

using ui::HeadlessInput;
using ui::Rect;
using ui::Region;
using ui::Workspace;

class PanelLayout : public InspectorUi {
  protected:
    // The image's rectangle (ViewerState x/y/w/h; the framebuffer scale is 1 offscreen).
    static Rect image(ui::HeadlessUi& ui) {
        const ui::ViewerState& v = ui.inspector().viewer();
        return {v.x, v.y, v.w, v.h};
    }
    // A press and a release of the left button at `at`, then a frame to draw what it chose.
    static void click(ui::HeadlessUi& ui, glm::vec2 at) {
        HeadlessInput in;
        in.mouse = at;
        ui.frame(in);  // hover first, as a real cursor arrives
        in.left = true;
        ui.frame(in);
        in.left = false;
        ui.frame(in);
        ui.frame(in);  // the selected tab is laid out one frame after the click
    }
    // No region and no drawn panel lies over the image; the image keeps its share.
    static void expect_clear_image(ui::HeadlessUi& ui, const std::string& when) {
        const Workspace& ws = ui.inspector().workspace();
        const Rect img = image(ui);
        const float width = float(ui.size().width);
        ASSERT_GT(img.w, 0.0f) << when;
        EXPECT_GE(img.w, Workspace::kViewerShare * width) << when;
        for (size_t r = 0; r < ui::kRegions; ++r)
            EXPECT_FALSE(ws.last_layout().regions[r].intersects(img))
                << when << ": region " << ui::region_name(Region(r));
        for (const auto& [name, rect] : ws.panel_rects())
            EXPECT_FALSE(rect.intersects(img)) << when << ": panel " << name;
        for (const auto& [name, rect] : ws.tab_rects())
            EXPECT_FALSE(rect.intersects(img)) << when << ": tab " << name;
        const Rect& viewer = ws.last_layout().viewer;
        EXPECT_TRUE(img.x >= viewer.x && img.right() <= viewer.right() && img.y >= viewer.y &&
                    img.bottom() <= viewer.bottom())
            << when << ": the image lies in the viewer's region";
    }
};

// The geometry alone, at any split a drag or an ini could ask for: regions never overlap the
// viewer or each other, stay inside the window, and the image keeps 55 % of the width.
TEST(PanelLayoutGeometry, RegionsNeverOverlapTheViewerAtAnySplit) {
    const std::vector<std::pair<float, float>> sizes = {
        {1600, 900}, {1280, 720}, {1920, 1080}, {960, 540}, {640, 360}};
    const std::vector<float> asked = {0, 1, 50, 180, 300, 500, 900, 5000};
    for (const auto& [w, h] : sizes)
        for (float left : asked)
            for (float right : asked)
                for (float bottom : {0.0f, 10.0f, 200.0f, 5000.0f}) {
                    const ui::WorkspaceLayout l = Workspace::layout({left, right, bottom}, w, h);
                    const std::string at = std::to_string(int(w)) + "x" + std::to_string(int(h)) +
                                           " asked " + std::to_string(int(left)) + "/" +
                                           std::to_string(int(right)) + "/" +
                                           std::to_string(int(bottom));
                    const float image_w = l.viewer.w - 2 * Workspace::kViewerPadding;
                    EXPECT_GE(image_w, Workspace::kViewerShare * w) << at;
                    EXPECT_GT(l.viewer.h, 0.0f) << at;
                    for (size_t r = 0; r < ui::kRegions; ++r) {
                        const Rect& rect = l.regions[r];
                        EXPECT_FALSE(rect.intersects(l.viewer)) << at << " region " << r;
                        for (size_t o = r + 1; o < ui::kRegions; ++o)
                            EXPECT_FALSE(rect.intersects(l.regions[o])) << at << " " << r << o;
                        EXPECT_GT(rect.w, 0.0f) << at;
                        EXPECT_GT(rect.h, 0.0f) << at;
                        EXPECT_GE(rect.x, 0.0f) << at;
                        EXPECT_LE(rect.right(), w) << at;
                        EXPECT_LE(rect.bottom(), h) << at;
                    }
                }
}

// At the two window sizes, every panel opened in turn by a real click on its tab
// header: the tab is selected, neither the camera nor a pick took the click, and no region,
// panel or tab lies over the image. Camera mode at one size, pick mode at the other: a click
// that reached the viewer would move the camera or pick a pixel.
TEST_F(PanelLayout, EveryTabHeaderIsClickableAndNoPanelCoversTheImage) {
    for (const VkExtent2D size : {VkExtent2D{1600, 900}, VkExtent2D{1280, 720}}) {
        auto ui = open("edges", {}, size);
        ui::Inspector& in = ui->inspector();
        const bool pick_mode = size.width == 1280;
        if (pick_mode) in.viewer().mouse = ui::MouseTarget::Pick;
        ui->frame();
        const std::string at = std::to_string(size.width) + "x" + std::to_string(size.height);
        expect_clear_image(*ui, at);
        for (const ui::PanelEntry& panel : ui::panel_list()) {
            const glm::vec3 camera = in.camera().position;
            const uint64_t picks = in.pixel_picks();
            ASSERT_TRUE(in.workspace().tab_rects().count(panel.name)) << panel.name;
            const Rect tab = in.workspace().tab_rects().at(panel.name);
            click(*ui, {tab.x + tab.w * 0.5f, tab.y + tab.h * 0.5f});
            EXPECT_EQ(in.workspace().open_tab(panel.region), panel.name) << at;
            EXPECT_TRUE(in.workspace().panel_rects().count(panel.name)) << at << panel.name;
            EXPECT_EQ(in.camera().position, camera) << at << ": " << panel.name;
            EXPECT_EQ(in.pixel_picks(), picks) << at << ": " << panel.name;
            expect_clear_image(*ui, at + " with " + panel.name + " open");
        }
        EXPECT_EQ(renderer_->validation_message_count(), 0u);
    }
}

// A split dragged with the mouse changes the sizes (the image widens; it never narrows below
// its share: expect_clear_image); imgui.ini keeps them and the open tabs, and a new session
// restores both, clamped to its window.
TEST_F(PanelLayout, ADraggedSplitAndTheOpenTabsSurviveTheIni) {
    std::string ini;
    float left = 0, bottom = 0;
    {
        auto ui = open("edges", {}, {1280, 720});
        ui::Inspector& in = ui->inspector();
        const ui::WorkspaceLayout before = in.workspace().last_layout();
        const glm::vec3 camera = in.camera().position;
        const float width_before = image(*ui).w;
        // The left splitter, 30 px to the left in two moves (at 1280 the defaults leave the
        // image its least width: to the right it does not go).
        HeadlessInput drag;
        drag.mouse = glm::vec2(before.splits.left + Workspace::kGap * 0.5f, 360.0f);
        ui->frame(drag);
        drag.left = true;
        ui->frame(drag);
        for (float dx : {-15.0f, -30.0f}) {
            drag.mouse = glm::vec2(before.splits.left + Workspace::kGap * 0.5f + dx, 360.0f);
            ui->frame(drag);
        }
        drag.left = false;
        ui->frame(drag);
        // The bottom splitter, 50 px up.
        const float split_y = before.viewer.bottom() + Workspace::kGap * 0.5f;
        drag.mouse = glm::vec2(before.viewer.x + before.viewer.w * 0.5f, split_y);
        ui->frame(drag);
        drag.left = true;
        ui->frame(drag);
        drag.mouse->y -= 50.0f;
        ui->frame(drag);
        drag.left = false;
        ui->frame(drag);
        ui->frame();
        const ui::Splits& s = in.workspace().splits();
        EXPECT_NEAR(s.left, before.splits.left - 30.0f, 1.0f);
        EXPECT_NEAR(s.bottom, before.splits.bottom + 50.0f, 1.0f);
        EXPECT_NEAR(image(*ui).w, width_before + 30.0f, 1.0f);
        EXPECT_EQ(in.camera().position, camera) << "the splitter took the drag";
        expect_clear_image(*ui, "after the drags");
        in.workspace().select("Depth");
        in.workspace().select("Scene");
        ui->frame();
        ui->frame();
        ini = ImGui::SaveIniSettingsToMemory();
        left = s.left;
        bottom = s.bottom;
    }
    EXPECT_NE(ini.find("[Workspace][layout]"), std::string::npos) << ini;
    EXPECT_NE(ini.find("tab_right=Depth"), std::string::npos) << ini;
    EXPECT_NE(ini.find("tab_left=Scene"), std::string::npos) << ini;

    auto ui = open("edges", {}, {1280, 720});
    ImGui::LoadIniSettingsFromMemory(ini.c_str(), ini.size());
    ui->frame();
    ui->frame();
    const Workspace& ws = ui->inspector().workspace();
    EXPECT_FLOAT_EQ(ws.last_layout().splits.left, left);
    EXPECT_FLOAT_EQ(ws.last_layout().splits.bottom, bottom);
    EXPECT_EQ(ws.open_tab(Region::Right), "Depth");
    EXPECT_EQ(ws.open_tab(Region::Left), "Scene");
    EXPECT_EQ(ws.open_tab(Region::Bottom), "Diagnose") << "the strip's first tab, as saved";

    // Sizes from a larger screen are clamped to this window: the image keeps its share.
    const std::string wide = "[Workspace][layout]\nleft=1500\nright=1400\nbottom=2000\n";
    ImGui::LoadIniSettingsFromMemory(wide.c_str(), wide.size());
    ui->frame();
    ui->frame();
    expect_clear_image(*ui, "restored from a larger screen");
    EXPECT_GE(ui->inspector().workspace().last_layout().viewer.h, Workspace::kMinViewerHeight);
}

}  // namespace
}  // namespace ds::test
