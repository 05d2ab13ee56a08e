// The Diagnose panel and button (issue 24 point 5): a diagnosis of the current view runs off
// the UI thread, its findings open in the Diagnose tab; selecting one highlights its pixels
// while the view is the one diagnosed and opens the panel with its details; a new scene drops
// it. Real lavapipe frames, validation on.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <set>
#include <string>

#include "capture/image_writer.h"
#include "renderer/passes/zfight.h"

#include "tests/unit/ui/inspector_ui.h"

namespace ds::test {
namespace {

using namespace std::chrono_literals;

class DiagnosePanel : public InspectorUi {
  protected:
    // UI frames until the diagnosis asked for is done (at most 5 minutes).
    static void until_diagnosed(ui::HeadlessUi& ui) {
        const auto deadline = std::chrono::steady_clock::now() + 300s;
        do {
            ui.frame();
        } while (ui.inspector().diagnosing() && std::chrono::steady_clock::now() < deadline);
        ui.frame();  // the panel draws what update() collected
    }
};

TEST_F(DiagnosePanel, AFindingShowsItsPixelsAndOpensItsPanelUntilTheViewChanges) {
    auto ui = open("decals", settings_of({"decal_pass=off"}), {1600, 900});
    ui::Inspector& in = ui->inspector();
    in.queue(ui::Diagnose{});
    ui->frame();
    EXPECT_TRUE(in.diagnosing());
    until_diagnosed(*ui);
    ASSERT_TRUE(in.diagnosis()) << in.diagnosis_error();
    EXPECT_EQ(in.workspace().open_tab(ui::Region::Bottom), "Diagnose");
    EXPECT_TRUE(in.diagnosis_current());
    const auto& findings = in.diagnosis()->findings;
    const auto fight = std::find_if(findings.begin(), findings.end(), [](const auto& f) {
        return f.code == "DECAL_ZFIGHT" && !f.pixels.empty();
    });
    ASSERT_NE(fight, findings.end());
    EXPECT_TRUE(in.selected_finding_pixels().empty()) << "nothing selected yet";

    in.queue(ui::SelectFinding{int(fight - findings.begin())});
    for (int i = 0; i < 3; ++i) ui->frame();  // the Depth tab shows; zfight's frame lands
    EXPECT_EQ(in.settings().get("zfight"), "on") << "the Depth panel's pairs need it";
    EXPECT_EQ(in.workspace().open_tab(ui::Region::Right), "Depth");
    EXPECT_TRUE(in.diagnosis_current()) << "a measurement knob changes no pixel";
    // The Depth panel's list has the finding's pair selected.
    const ZfightResult* z = in.frame().find<ZfightResult>();
    ASSERT_TRUE(z);
    ASSERT_GE(in.viewer().zfight_pair, 0);
    const ZfightPair& pair = z->pairs[size_t(in.viewer().zfight_pair)];
    ASSERT_EQ(fight->surfaces.size(), 2u);
    EXPECT_EQ((std::set<std::string>{pair.a.node, pair.b.node}),
              (std::set<std::string>{fight->surfaces[0].node, fight->surfaces[1].node}));
    if (const char* dir = std::getenv("DS_TEST_SHOTS"))  // to look at
        capture::write_png_rgba8(std::string(dir) + "/diagnose_selected.png", ui->size().width,
                                 ui->size().height, ui->frame());
    const std::vector<uint8_t> mask = in.selected_finding_pixels();
    EXPECT_EQ(size_t(std::count(mask.begin(), mask.end(), uint8_t(1))), fight->pixels.size());

    // Another view: the list stays, its pixels no longer match the image.
    ui::HeadlessInput f;
    const ui::ViewerState& v = in.viewer();
    f.mouse = glm::vec2(v.x + v.w * 0.5f, v.y + v.h * 0.5f);
    f.keys = {int('F')};
    ui->frame(f);
    ui->frame();
    EXPECT_FALSE(in.diagnosis_current());
    EXPECT_TRUE(in.selected_finding_pixels().empty());
    ASSERT_TRUE(in.diagnosis());

    in.queue(ui::LoadScene{"edges"});
    ui->frame();
    EXPECT_FALSE(in.diagnosis());
    EXPECT_EQ(in.viewer().finding, -1);
    EXPECT_EQ(renderer_->validation_message_count(), 0u);
}

}  // namespace
}  // namespace ds::test
