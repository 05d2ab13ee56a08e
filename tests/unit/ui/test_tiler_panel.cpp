// The Tiler panel and the Passes panel on render_path=subpass, offscreen on lavapipe with
// validation: switching the path from the inspector gives the frame its render pass, whose
// verdict the panel shows; DS_TILER_PNG writes the UI with both panels open.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include <imgui.h>

#include "capture/image_writer.h"
#include "renderer/scene/loader.h"
#include "tests/gpu/passes/shared_renderer.h"
#include "ui/headless.h"
#include "ui/panels/panels.h"

namespace ds::test {
namespace {

using ui::HeadlessUi;

class TilerPanel : public SharedRenderer {};

TEST_F(TilerPanel, SwitchingToTheSubpassPathShowsTheRenderPassAndItsVerdict) {
    HeadlessUi ui(*renderer_, Settings{}, scene::load_scene("atrium", Settings{}), {1280, 800});
    ui.frame();  // lays the panels out
    ui::Inspector& in = ui.inspector();
    EXPECT_FALSE(in.frame().tiler);  // dynamic: nothing to merge
    in.workspace().select("Tiler");
    in.queue(ui::SetSetting{"render_path", "subpass"});
    ui.frame();
    ui.frame();  // the panels draw the subpass frame; its tables fit their columns
    const std::vector<uint8_t> pixels = ui.frame();
    ASSERT_TRUE(in.frame().tiler);
    EXPECT_EQ(in.frame().tiler->verdict, "a tiler can merge these subpasses: yes");
    size_t nested = 0;
    for (const PassResult& p : in.frame().passes) nested += p.subpass_group == "gbuffer_lighting";
    EXPECT_GE(nested, 2u);  // the Passes panel's nested rows
    EXPECT_EQ(renderer_->validation_message_count(), 0u);
    if (const char* png = std::getenv("DS_TILER_PNG"))
        capture::write_png_rgba8(png, ui.size().width, ui.size().height, pixels);
}

}  // namespace
}  // namespace ds::test
