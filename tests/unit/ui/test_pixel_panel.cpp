// The Pixel panel and PickPixel through the inspector, offscreen on lavapipe with validation:
// the pixel-history cases through the inspector's action, and a real click in pick
// mode.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include <imgui.h>

#include "capture/image_writer.h"
#include "renderer/passes/pixel_history.h"
#include "tests/unit/ui/inspector_ui.h"

namespace ds::test {
namespace {

using ui::HeadlessInput;

class PixelPanel : public InspectorUi {};

// The Pixel panel: PickPixel through the inspector's renderer, camera, size and settings. On
// overdraw (every layer covers the whole view) the prepass lists the eight layers front to
// back, only the first passing, and forward exactly one passing fragment, the front layer's;
// then a click in the viewer's "pick" mode asks for the texel under the cursor.
TEST_F(PixelPanel, PickPixelListsTheOverdrawLayersAndAClickPicks) {
    auto ui = open("overdraw", {}, {1280, 720});
    ui::Inspector& in = ui->inspector();
    EXPECT_FALSE(in.pixel_history());
    const VkExtent2D size = in.render_size();
    const uint32_t x = size.width / 3, y = size.height / 2;
    in.queue(ui::PickPixel{x, y});
    ui->frame();
    ASSERT_TRUE(in.pixel_history()) << in.pixel_error();
    EXPECT_EQ(in.pixel_history()->x, x);
    size_t prepass = 0, prepass_passed = 0, forward_passed = 0;
    for (const PixelFragment& f : in.pixel_history()->fragments) {
        if (f.pass == "depth_prepass") {
            EXPECT_EQ(f.depth_passed, prepass == 0) << prepass;
            EXPECT_EQ(in.scene().instance_name(f.instance).material,
                      "layer_" + std::to_string(prepass));
            prepass_passed += f.depth_passed;
            ++prepass;
        } else if (f.pass == "forward" && f.depth_passed) {
            ++forward_passed;
            EXPECT_EQ(in.scene().instance_name(f.instance).material, "layer_0");
        }
    }
    EXPECT_EQ(prepass, 8u);
    EXPECT_EQ(prepass_passed, 1u);
    EXPECT_EQ(forward_passed, 1u);
    EXPECT_EQ(in.pixel_label(),
              "overdraw at " + std::to_string(size.width) + "x" + std::to_string(size.height));
    // The inspector's own frame has no replay passes: it renders the settings as set.
    for (const PassResult& p : in.frame().passes) EXPECT_NE(p.role, graph::PassRole::History);
    // Outside the frame: an error in the panel, the last history kept.
    in.queue(ui::PickPixel{size.width, 0});
    ui->frame();
    EXPECT_FALSE(in.pixel_error().empty());
    EXPECT_EQ(in.pixel_history()->x, x);

    // A click in pick mode: the texel under the cursor (press, then release without moving).
    in.workspace().select("Draws");  // another tab of the strip the Pixel panel is in
    ui->frame();
    ui->frame();
    ASSERT_EQ(in.workspace().open_tab(ui::Region::Bottom), "Draws");
    in.viewer().mouse = ui::MouseTarget::Pick;
    const glm::vec3 camera = in.camera().position;
    HeadlessInput click;
    click.mouse = screen_of(*ui, 17, 23);
    click.left = true;
    ui->frame(click);
    click.left = false;
    ui->frame(click);
    ASSERT_TRUE(in.pixel_history()) << in.pixel_error();
    EXPECT_EQ(in.pixel_history()->x, 17u);
    EXPECT_EQ(in.pixel_history()->y, 23u);
    EXPECT_EQ(in.pixel_history()->fragments.size(), 16u);  // 8 prepass + 8 forward
    EXPECT_EQ(in.camera().position, camera);               // pick mode leaves the camera
    // A pick shows the Pixel panel's tab (selected at the next frame, drawn at the one after),
    // which draws the table (an ImGui assertion would abort here).
    ui->frame();
    ui->frame();
    EXPECT_EQ(in.workspace().open_tab(ui::Region::Bottom), "Pixel") << "a pick shows its history";
    const std::vector<uint8_t> pixels = ui->frame();
    if (const char* png = std::getenv("DS_PIXEL_PNG"))
        capture::write_png_rgba8(png, 1280, 720, pixels);
}

// The other two pixel-history cases through the inspector's action: overdraw with the
// prepass off (every layer in authored order, all passing), and a foliage pixel where the
// frame's own prepass_discarded image says a cut-out was discarded (a masked prepass
// A scene switch drops what was picked: the history named atrium's instances (224 of them),
// and the Pixel panel read them with foliage's names (24 instances): out of range, a crash
// once the panel drew (the issue: "vector::_M_range_check: __n (which is 129)").
TEST_F(PixelPanel, ASceneSwitchDropsThePickAndTheSelectedPair) {
    auto ui = open("atrium", {}, {960, 540});
    ui::Inspector& in = ui->inspector();
    const VkExtent2D size = in.render_size();
    uint32_t highest = 0;
    for (uint32_t k = 1; k < 8 && highest < 24; ++k) {  // until an instance foliage lacks
        in.queue(ui::PickPixel{size.width * k / 8, size.height / 3});
        ui->frame();
        ASSERT_TRUE(in.pixel_history()) << in.pixel_error();
        for (const PixelFragment& f : in.pixel_history()->fragments)
            highest = std::max(highest, f.instance);
    }
    ASSERT_GE(highest, 24u) << "no picked fragment names an instance foliage lacks";
    in.viewer().zfight_pair = 0;
    in.queue(ui::LoadScene{"foliage"});
    for (int i = 0; i < 3; ++i) ui->frame();  // every panel draws with the new scene
    EXPECT_EQ(in.scene().name, "foliage");
    EXPECT_FALSE(in.pixel_history());
    EXPECT_FALSE(in.pixel_samples());
    EXPECT_TRUE(in.pixel_label().empty());
    EXPECT_EQ(in.viewer().zfight_pair, -1);
}

// fragment, alpha below the cutoff).
TEST_F(PixelPanel, PickPixelWithoutPrepassAndInAFoliageCutOut) {
    auto ui = open("overdraw", settings_of({"prepass=off"}), {1280, 720});
    ui::Inspector& in = ui->inspector();
    in.queue(ui::PickPixel{40, 30});
    ui->frame();
    ASSERT_TRUE(in.pixel_history()) << in.pixel_error();
    std::vector<std::string> layers;
    for (const PixelFragment& f : in.pixel_history()->fragments) {
        EXPECT_EQ(f.pass, "forward");
        EXPECT_TRUE(f.depth_passed);  // back to front: each is closer than the last
        layers.push_back(in.scene().instance_name(f.instance).material);
    }
    ASSERT_EQ(layers.size(), 8u);
    EXPECT_EQ(layers.back(), "layer_0");  // the front layer, drawn last

    auto foliage = open("foliage", settings_of({"count_fragments=on"}), {1280, 720});
    ui::Inspector& fin = foliage->inspector();
    fin.queue(ui::SelectResource{"prepass_discarded"});
    foliage->frame();
    const InspectedImage* discarded = fin.shown();
    ASSERT_TRUE(discarded && discarded->name == "prepass_discarded");
    std::optional<std::array<uint32_t, 2>> cut;
    for (uint32_t i = 0; i < discarded->width * discarded->height && !cut; ++i)
        if (discarded->texels[size_t(i) * 4] > 0.0f)
            cut = std::array{i % discarded->width, i / discarded->width};
    ASSERT_TRUE(cut) << "foliage discards somewhere";
    fin.queue(ui::PickPixel{(*cut)[0], (*cut)[1]});
    foliage->frame();
    ASSERT_TRUE(fin.pixel_history()) << fin.pixel_error();
    size_t cut_out = 0;
    for (const PixelFragment& f : fin.pixel_history()->fragments) {
        if (f.pass != "depth_prepass" || !f.alpha_test || f.alpha_test->passed) continue;
        EXPECT_LT(f.alpha_test->alpha, f.alpha_test->cutoff);
        EXPECT_TRUE(f.shaded);  // the masked pipeline tests depth late: it ran, then discarded
        ++cut_out;
    }
    EXPECT_EQ(cut_out,
              size_t(discarded->texels[(size_t((*cut)[1]) * discarded->width + (*cut)[0]) * 4]));
}

}  // namespace
}  // namespace ds::test
