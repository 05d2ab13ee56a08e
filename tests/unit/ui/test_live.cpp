// The live inspector as the window runs it: the UI on a device of its own, scene frames on the
// inspector's render thread, rendered only when something changed (ui/inspector_frames.cpp).
// Real lavapipe, validation on both devices (any message fails the test).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <thread>

#include "capture/image_writer.h"
#include "renderer/scene/loader.h"
#include "tests/gpu/passes/shared_renderer.h"
#include "ui/headless.h"

namespace ds::test {
namespace {

using namespace std::chrono_literals;
using ui::HeadlessInput;
using ui::HeadlessUi;

vk::ContextOptions validated() {
    vk::ContextOptions o;
    o.validate = true;
    return o;
}

// The cursor at `p`, the left button down or not.
HeadlessInput mouse_at(glm::vec2 p, bool left = false) {
    HeadlessInput in;
    in.mouse = p;
    in.left = left;
    return in;
}

class LiveInspector : public SharedRenderer {
  protected:
    std::unique_ptr<HeadlessUi> open(const std::string& scene_name, Settings settings = {}) {
        scene::Scene scene = scene::load_scene(scene_name, settings);
        return std::make_unique<HeadlessUi>(*renderer_, settings, std::move(scene),
                                            VkExtent2D{640, 400}, std::nullopt, validated());
    }
    // UI frames until the scene frame in flight has arrived (and the UI is idle); the count.
    static int until_shown(HeadlessUi& ui, const HeadlessInput& input = {}) {
        int frames = 0;
        const auto deadline = std::chrono::steady_clock::now() + 120s;
        do {
            ui.frame(input);
            ++frames;
        } while ((ui.inspector().rendering() || ui.inspector().worker().has_finished()) &&
                 std::chrono::steady_clock::now() < deadline);
        ui.frame(input);  // takes a frame that finished during the last one
        return frames + 1;
    }
    // UI frames until `count` scene frames have arrived in all (continuous: one is always in
    // flight).
    static void until_rendered(HeadlessUi& ui, uint64_t count) {
        const auto deadline = std::chrono::steady_clock::now() + 120s;
        while (ui.inspector().frames_rendered() < count &&
               std::chrono::steady_clock::now() < deadline)
            ui.frame();
        ASSERT_GE(ui.inspector().frames_rendered(), count);
    }
};

TEST_F(LiveInspector, UiFramesContinueWhileASlowSceneFrameRenders) {
    auto ui = open("atrium");
    ui::Inspector& in = ui->inspector();
    until_shown(*ui);
    ASSERT_EQ(in.frames_rendered(), 1u);

    in.worker().set_frame_delay(2500ms);  // the hook: one scene frame takes 2.5 s longer
    in.queue(ui::SetSetting{"gtao", "off"});
    ui->frame();  // posts it
    ASSERT_TRUE(in.rendering());
    int during = 0;
    const auto start = std::chrono::steady_clock::now();
    while (in.rendering() && std::chrono::steady_clock::now() - start < 60s) {
        const std::vector<uint8_t> pixels = ui->frame();
        if (const char* png = std::getenv("DS_LIVE_PNG"); png && during == 10)
            capture::write_png_rgba8(png, ui->size().width, ui->size().height, pixels);
        ++during;
        EXPECT_EQ(in.frames_rendered(), 1u);  // the frame shown is the older one meanwhile
    }
    in.worker().set_frame_delay(0ms);
    ui->frame();
    EXPECT_GE(during, 20) << "UI frames while one slow scene frame rendered";
    std::printf("UI frames during the slow scene frame: %d\n", during);
    EXPECT_EQ(in.frames_rendered(), 2u);
    EXPECT_EQ(in.frame().passes.end(),
              std::find_if(in.frame().passes.begin(), in.frame().passes.end(),
                           [](const PassResult& p) { return p.name == "gtao"; }));
    EXPECT_EQ(ui->ui_validation_messages(), 0u);
}

// A frame that lands is shown with no input: the panels draw before update() collects it, so
// the UI frame that collects it is not the last one; the inspector is idle (the window would
// sleep until an event) only once the panels have drawn it.
TEST_F(LiveInspector, AFrameThatLandsIsDrawnBeforeTheUiSleeps) {
    auto ui = open("edges");
    ui::Inspector& in = ui->inspector();
    for (int round = 0; round < 2; ++round) {  // the first frame, then a setting's
        if (round == 1) in.queue(ui::SetSetting{"sun_azimuth", "80"});
        const uint64_t before = in.frames_rendered();
        const auto deadline = std::chrono::steady_clock::now() + 120s;
        while (in.frames_rendered() == before && std::chrono::steady_clock::now() < deadline) {
            ui->frame();  // idle only once the frame has been drawn
            if (in.frames_rendered() == before) std::this_thread::sleep_for(5ms);
        }
        ASSERT_GT(in.frames_rendered(), before) << "round " << round;
        EXPECT_FALSE(in.idle()) << "round " << round << ": collected after the panels drew";
        ui->frame();
        EXPECT_FALSE(in.idle()) << "round " << round << ": tables fit at the second UI frame";
        ui->frame();
        EXPECT_TRUE(in.idle()) << "round " << round;
    }
    EXPECT_EQ(ui->ui_validation_messages(), 0u);
}

// UI frames with `input` until the inspector is idle (where the window would sleep until an
// event), at most 120 s.
void until_idle(HeadlessUi& ui, const HeadlessInput& input = {}) {
    const auto deadline = std::chrono::steady_clock::now() + 120s;
    do {
        ui.frame(input);
        std::this_thread::sleep_for(5ms);
    } while (!ui.inspector().idle() && std::chrono::steady_clock::now() < deadline);
    ASSERT_TRUE(ui.inspector().idle());
}

// Where the window would go to sleep after a scene switch, the new scene's frame is drawn: its
// passes' timings and the viewer's image, not the previous scene's.
TEST_F(LiveInspector, AfterASceneSwitchTheNewScenesFrameIsDrawnBeforeTheUiSleeps) {
    auto ui = open("edges");
    ui::Inspector& in = ui->inspector();
    until_idle(*ui);
    const uint64_t before = in.frames_rendered();
    in.queue(ui::LoadScene{"overdraw"});
    until_idle(*ui);
    EXPECT_EQ(in.scene().name, "overdraw");
    EXPECT_GT(in.frames_rendered(), before);
    EXPECT_EQ(in.frames_drawn(), in.frames_rendered());
    const VkExtent2D full = in.render_size();
    EXPECT_EQ(in.frame().width, full.width);
    EXPECT_EQ(in.frame().height, full.height);
    EXPECT_EQ(ui->ui_validation_messages(), 0u);
}

// A wheel dolly renders a motion-scaled frame; with no more input, the full-size frame replaces
// it before the UI sleeps (it used to stay on screen until the mouse moved).
// (edges: its scaled frame lands within the motion hold, which is when it stayed.)
TEST_F(LiveInspector, AfterAWheelDollyTheFullSizeFrameIsShownBeforeTheUiSleeps) {
    auto ui = open("edges");
    ui::Inspector& in = ui->inspector();
    until_idle(*ui);
    const VkExtent2D full = in.render_size();
    const uint64_t before = in.frames_rendered();
    const ui::ViewerState& v = in.viewer();
    const glm::vec2 centre{v.x + v.w / 2, v.y + v.h / 2};
    HeadlessInput wheel = mouse_at(centre);
    wheel.wheel = 1.0f;
    ui->frame(wheel);
    ASSERT_TRUE(in.moving());
    until_idle(*ui, mouse_at(centre));  // the cursor rests where it was: no input
    EXPECT_GE(in.frames_rendered(), before + 2) << "the scaled frame, then the full size";
    EXPECT_EQ(in.frame().width, full.width);
    EXPECT_EQ(in.frame().height, full.height);
    EXPECT_EQ(in.frames_drawn(), in.frames_rendered());
    EXPECT_EQ(ui->ui_validation_messages(), 0u);
}

TEST_F(LiveInspector, RendersOnlyWhenSomethingChanged) {
    auto ui = open("edges");
    ui::Inspector& in = ui->inspector();
    until_shown(*ui);
    const uint64_t posted = in.frames_posted(), rendered = in.frames_rendered();
    for (int i = 0; i < 10; ++i) ui->frame();
    EXPECT_EQ(in.frames_posted(), posted) << "no input, no change: no scene frame";
    EXPECT_EQ(in.frames_rendered(), rendered);
    EXPECT_TRUE(in.idle());

    // Another resource is read back by a new frame (and its legend's row, a smaller viewer, may
    // take one more); the decode range is view state: decoded again, nothing renders.
    in.queue(ui::SelectResource{"depth"});
    until_shown(*ui);
    const uint64_t depth_posted = in.frames_posted();
    EXPECT_GT(depth_posted, posted);
    EXPECT_TRUE(in.shown() && in.shown()->name == "depth");
    const std::vector<uint8_t> before = in.view().rgba8;
    in.viewer().params.auto_fit = false;
    in.viewer().params.black = 0.0f;
    in.viewer().params.white = 0.5f;
    ui->frame();
    EXPECT_EQ(in.frames_posted(), depth_posted);
    EXPECT_NE(in.view().rgba8, before) << "decoded again with the new range";

    // A setting renders one frame, then nothing more.
    in.queue(ui::SetSetting{"sun_azimuth", "80"});
    until_shown(*ui);
    for (int i = 0; i < 5; ++i) ui->frame();
    EXPECT_EQ(in.frames_posted(), depth_posted + 1);
    EXPECT_TRUE(in.idle());

    // continuous: a frame whenever the last one is done.
    in.queue(ui::SetSetting{"continuous", "on"});
    until_rendered(*ui, in.frames_rendered() + 3);
    EXPECT_GE(in.frames_posted(), depth_posted + 4);
    EXPECT_FALSE(in.idle());
    EXPECT_EQ(ui->ui_validation_messages(), 0u);
}

TEST_F(LiveInspector, MovingRendersAtMotionScaleAndTheFullSizeWhenItStops) {
    auto ui = open("atrium");
    ui::Inspector& in = ui->inspector();
    until_shown(*ui);
    const VkExtent2D full = in.render_size();
    ASSERT_EQ(in.frame().width, full.width);
    const ui::ViewerBlit still = in.viewer_blit();

    // Orbit: left drag across the viewer, a frame at a time.
    const ui::ViewerState& v = in.viewer();
    const glm::vec2 centre{v.x + v.w / 2, v.y + v.h / 2};
    HeadlessInput drag = mouse_at(centre, true);
    ui->frame(drag);
    // The mouse moves every UI frame until a frame rendered meanwhile arrives (posted in the
    // update that moved the camera: moving() is true then, whatever the UI frames' pace).
    for (int i = 1; i <= 2000 && in.frames_rendered() < 2; ++i) {
        drag.mouse = centre + glm::vec2(0.5f * float(i % 200), 0.0f);
        ui->frame(drag);
    }
    ASSERT_EQ(in.frames_rendered(), 2u);
    EXPECT_EQ(in.frame().width, uint32_t(std::lround(full.width * 0.5)));
    EXPECT_EQ(in.frame().height, uint32_t(std::lround(full.height * 0.5)));
    // The smaller frame fills the same viewport: the blit's source spans the whole image.
    const ui::ViewerBlit moving = in.viewer_blit();
    EXPECT_NEAR(moving.src_w / float(moving.width), still.src_w / float(still.width), 1e-3f);

    // Released and still for longer than the motion hold: one full-size frame.
    ui->frame(mouse_at(*drag.mouse));
    std::this_thread::sleep_for(300ms);
    until_shown(*ui, mouse_at(*drag.mouse));
    EXPECT_FALSE(in.moving());
    EXPECT_EQ(in.frame().width, full.width);
    EXPECT_EQ(in.frame().height, full.height);
    EXPECT_EQ(ui->ui_validation_messages(), 0u);
}

// A frame posted with the camera at rest starts the temporal AO over; with the camera still,
// the temporal pass's fixed point is its input, so that frame is what many frames converge to.
// motion_scale 1: the frames while orbiting have the full size, so their AO history would carry
// over into the frame at rest without the cut.
TEST_F(LiveInspector, TheFirstFrameAtRestIsTheConvergedOne) {
    auto ui = open("atrium", settings_of({"motion_scale=1"}));
    ui::Inspector& in = ui->inspector();
    in.queue(ui::SelectResource{"ao"});
    until_shown(*ui);
    const ui::ViewerState& v = in.viewer();
    const glm::vec2 centre{v.x + v.w / 2, v.y + v.h / 2};
    HeadlessInput drag = mouse_at(centre, true);
    ui->frame(drag);
    for (int i = 1; i <= 2000 && in.frames_rendered() < 5; ++i) {  // a few frames while moving
        drag.mouse = centre + glm::vec2(0.5f * float(i % 200), 0.2f * float(i % 200));
        ui->frame(drag);
    }
    ui->frame(mouse_at(*drag.mouse));
    std::this_thread::sleep_for(300ms);
    until_shown(*ui);
    ASSERT_FALSE(in.moving());
    ASSERT_TRUE(in.shown() && in.shown()->name == "ao");
    const std::vector<float> first = in.shown()->texels;
    in.queue(ui::SetSetting{"continuous", "on"});
    until_rendered(*ui, in.frames_rendered() + 12);
    ASSERT_TRUE(in.shown() && in.shown()->name == "ao");
    const std::vector<float>& later = in.shown()->texels;
    ASSERT_EQ(first.size(), later.size());
    float worst = 0.0f;
    for (size_t i = 0; i < first.size(); i += 4)
        worst = std::max(worst, std::abs(first[i] - later[i]));
    EXPECT_LE(worst, 1.5f / 255.0f) << "AO moved after the first frame at rest";
}

TEST_F(LiveInspector, ARefusedSettingFromTheRenderThreadReachesTheUi) {
    auto ui = open("edges");
    ui::Inspector& in = ui->inspector();
    until_shown(*ui);
    const uint64_t shown = in.frames_rendered();
    // The registry takes znear=0 (the planes are checked against the scene's when rendering):
    // the render thread refuses it, on every device.
    in.queue(ui::SetSetting{"znear", "0"});
    until_shown(*ui);
    until_shown(*ui);  // the last good settings render again
    EXPECT_EQ(in.settings().get("znear"), "scene");
    EXPECT_NE(in.message().find("near plane must be above 0"), std::string::npos) << in.message();
    EXPECT_EQ(in.frames_rendered(), shown + 1) << "the refused frame is not shown";
    ui->frame();  // a new frame is drawn twice before the UI sleeps (its tables fit late)
    EXPECT_TRUE(in.idle());
}

}  // namespace
}  // namespace ds::test
