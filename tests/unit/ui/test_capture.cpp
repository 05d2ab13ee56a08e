// Captures from the inspector and the compare view, offscreen (ui::HeadlessUi) on lavapipe with
// validation: F12 writes a normal capture of what the viewer shows (its camera, settings and
// render size) that `depthscope replay` renders again bit for bit; the compare view finds no
// difference against it and a difference against another exposure; sizes that differ are said,
// not drawn; a capture that cannot be written is one line and the inspector goes on.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>

#include <imgui.h>
#include <nlohmann/json.hpp>

#include "capture/image_writer.h"
#include "tests/support/run_process.h"
#include "tests/unit/ui/inspector_ui.h"

namespace ds::test {
namespace {

namespace fs = std::filesystem;
using ui::CompareMode;
using ui::HeadlessInput;
using ui::HeadlessUi;

nlohmann::json read_json(const fs::path& path) {
    std::ifstream in(path);
    return nlohmann::json::parse(in);
}

glm::vec3 vec3(const nlohmann::json& j) {
    return {j[0].get<float>(), j[1].get<float>(), j[2].get<float>()};
}

class InspectorCapture : public InspectorUi {
  protected:
    // F12, and the UI frames until the capture is written: "capturing…" is shown first.
    static void press_f12(HeadlessUi& ui) {
        HeadlessInput in;
        in.pressed = {ui::Inspector::kCaptureKey};
        ui.frame(in);
        ASSERT_TRUE(ui.inspector().capturing());
        ui.frame();
        ASSERT_TRUE(ui.inspector().capturing());  // presented with "capturing…"
        ui.frame();
        ASSERT_FALSE(ui.inspector().capturing());
    }
    static size_t non_black(const std::vector<uint8_t>& rgba8) {
        size_t n = 0;
        for (size_t i = 0; i < rgba8.size(); i += 4)
            n += rgba8[i] || rgba8[i + 1] || rgba8[i + 2] ? 1 : 0;
        return n;
    }
    // The UI with the Compare panel open, written where the test's files go (to look at).
    static void screenshot(HeadlessUi& ui, const fs::path& file) {
        ui.inspector().workspace().select("Compare");
        ui.frame();
        const std::vector<uint8_t> pixels = ui.frame();
        capture::write_png_rgba8(file, ui.size().width, ui.size().height, pixels);
    }
};

TEST_F(InspectorCapture, F12WritesTheViewersFrameAndReplayIsBitIdentical) {
    auto ui = open("edges", settings_of({"exposure=1.5"}), {640, 360});
    ui::Inspector& in = ui->inspector();
    const fs::path root = fresh_dir("inspector_capture_f12");
    in.set_capture_root(root);
    in.camera_input().orbit = {60.0f, -25.0f};  // away from the scene's own camera
    ui->frame();
    const scene::Camera camera = in.camera();
    ASSERT_NE(camera.position, in.scene().camera.position);
    const VkExtent2D size = in.render_size();
    in.viewer().compare.mode = CompareMode::Diff;  // the frame after the capture is compared

    press_f12(*ui);
    ASSERT_EQ(in.capture_error(), "");
    const fs::path dir = in.capture_path();
    ASSERT_EQ(dir.parent_path(), root);
    ASSERT_EQ(in.captures_written(), std::vector<fs::path>{dir});
    EXPECT_TRUE(fs::is_regular_file(dir / "final.png"));
    EXPECT_FALSE(fs::is_empty(dir / "resources"));
    const nlohmann::json report = read_json(dir / "report.json");
    // The inspector's camera, exactly (floats survive report.json's doubles), size, settings.
    const nlohmann::json& c = report["replay"]["camera"];
    EXPECT_EQ(vec3(c["position"]), camera.position);
    EXPECT_EQ(vec3(c["forward"]), camera.forward);
    EXPECT_EQ(vec3(c["up"]), camera.up);
    EXPECT_EQ(c["yfov"].get<float>(), camera.yfov);
    EXPECT_EQ(c["znear"].get<float>(), camera.znear);
    EXPECT_EQ(c["zfar"].get<float>(), camera.zfar);
    EXPECT_EQ(report["size"]["width"], size.width);
    EXPECT_EQ(report["size"]["height"], size.height);
    EXPECT_EQ(report["settings"]["exposure"], "1.5");
    // Every resource, as `capture` writes by default: a PNG and an EXR each.
    const auto files = std::distance(fs::directory_iterator(dir / "resources"), {});
    EXPECT_GT(report["resources"].size(), 10u);
    EXPECT_EQ(size_t(files), 2 * report["resources"].size());

    // Pinned; the next live frame starts from a camera cut: it is the captured frame.
    ASSERT_TRUE(in.compare().pinned());
    EXPECT_EQ(in.compare().pinned()->dir, dir);
    const Png png = read_png(dir / "final.png");
    EXPECT_EQ(in.frame().rgba8, png.rgba);
    ASSERT_TRUE(in.compare().differing());
    EXPECT_EQ(*in.compare().differing(), 0u);
    EXPECT_EQ(in.compare().width(), size.width);

    const ProcessResult replay = run_depthscope("replay " + dir.string() + " --out " +
                                                (root / "replay").string() + " --resources none");
    EXPECT_EQ(replay.exit_code, 0) << replay.err;
    EXPECT_NE(replay.out.find("final.png is bit-identical"), std::string::npos) << replay.out;
}

TEST_F(InspectorCapture, CompareFindsNothingOnTheSameFrameAndAnotherExposureInDiffAndSplit) {
    auto ui = open("atrium", {}, {1280, 720});  // large enough to read the screenshots
    ui::Inspector& in = ui->inspector();
    const fs::path root = fresh_dir("inspector_capture_compare");
    in.set_capture_root(root);
    press_f12(*ui);
    ASSERT_EQ(in.capture_error(), "");
    const Png shot = read_png(in.capture_path() / "final.png");
    ui::CompareState& compare = in.viewer().compare;
    compare.mode = CompareMode::Diff;
    for (int i = 0; i < 2; ++i) {  // with temporal history again: the same still frame
        ui->frame();
        ASSERT_TRUE(in.compare().differing());
        EXPECT_EQ(*in.compare().differing(), 0u) << "frame " << i;
        EXPECT_EQ(non_black(in.compare().rgba8()), 0u);
    }
    // Split, the same frame on both sides: only the divider's column is not the frame.
    compare.mode = CompareMode::Split;
    ui->frame();
    const uint32_t w = in.compare().width(), h = in.compare().height();
    const uint32_t column = uint32_t(std::lround(0.5f * float(w)));  // the divider's
    ASSERT_EQ(in.viewer_blit().rgba8, &in.compare().rgba8());
    for (uint32_t y = 0; y < h; y += 7)
        for (uint32_t x = 0; x < w; x += 5) {
            const size_t i = (size_t(y) * w + x) * 4;
            if (x == column) continue;
            ASSERT_EQ(in.compare().rgba8()[i + 1], in.frame().rgba8[i + 1]) << x << "," << y;
        }
    const uint8_t* line = &in.compare().rgba8()[(size_t(h / 2) * w + column) * 4];
    EXPECT_EQ(std::vector<uint8_t>(line, line + 4), (std::vector<uint8_t>{255, 210, 0, 255}));

    // Another exposure: pixels differ, the heat map lights exactly those.
    in.queue(ui::SetSetting{"exposure", "2"});
    compare.mode = CompareMode::Diff;
    ui->frame();
    ASSERT_TRUE(in.compare().differing());
    const uint64_t differing = *in.compare().differing();
    EXPECT_GT(in.compare().percent(), 1.0);
    EXPECT_EQ(non_black(in.compare().rgba8()), differing);
    screenshot(*ui, root / "compare_diff_ui.png");
    // Split: the live (brighter) frame left of the divider, the capture from it on.
    compare.mode = CompareMode::Split;
    compare.divider = 0.25f;
    ui->frame();
    const std::vector<uint8_t>& split = in.compare().rgba8();
    const uint32_t at = uint32_t(std::lround(0.25f * float(w)));
    for (uint32_t y = 0; y < h; y += 11) {
        const size_t row = size_t(y) * w * 4;
        EXPECT_TRUE(std::equal(split.begin() + long(row), split.begin() + long(row + at * 4),
                               in.frame().rgba8.begin() + long(row)));
        EXPECT_TRUE(std::equal(split.begin() + long(row + (at + 1) * 4),
                               split.begin() + long(row + w * 4),
                               shot.rgba.begin() + long(row + (at + 1) * 4)));
    }
    screenshot(*ui, root / "compare_split_ui.png");
}

TEST_F(InspectorCapture, SizesThatDifferAreSaidAndMatchingTheCapturesSizeComparesAgain) {
    auto ui = open("edges", {}, {640, 360});
    ui::Inspector& in = ui->inspector();
    in.set_capture_root(fresh_dir("inspector_capture_sizes"));
    press_f12(*ui);
    ASSERT_EQ(in.capture_error(), "");
    const VkExtent2D captured = in.render_size();
    in.viewer().compare.mode = CompareMode::Diff;
    in.queue(ui::SetSetting{"render_scale", "0.5"});
    ui->frame();
    EXPECT_NE(in.frame().width, captured.width);
    EXPECT_NE(in.compare().status().find("sizes differ: live "), std::string::npos)
        << in.compare().status();
    EXPECT_TRUE(in.compare().rgba8().empty());
    EXPECT_FALSE(in.compare().differing());
    EXPECT_EQ(in.viewer_blit().width, in.frame().width);  // the live image, not a comparison

    in.viewer().compare.match_size = true;  // render_scale does not change the pixels
    ui->frame();
    EXPECT_EQ(in.frame().width, captured.width);
    EXPECT_EQ(in.frame().height, captured.height);
    EXPECT_EQ(in.compare().status(), "");
    ASSERT_TRUE(in.compare().differing());
    EXPECT_EQ(*in.compare().differing(), 0u);
}

TEST_F(InspectorCapture, ACaptureThatCannotBeWrittenIsOneLineAndTheInspectorGoesOn) {
    auto ui = open("edges", {}, {480, 270});
    ui::Inspector& in = ui->inspector();
    const fs::path root = fresh_dir("inspector_capture_bad") / "not_a_folder";
    std::ofstream(root) << "x";
    in.set_capture_root(root);
    const uint64_t frames = in.frames_rendered();
    press_f12(*ui);
    EXPECT_EQ(in.frames_rendered(), frames + 3);  // the frames went on
    EXPECT_NE(in.capture_error(), "");
    EXPECT_EQ(in.capture_error().find('\n'), std::string::npos) << in.capture_error();
    EXPECT_TRUE(in.capture_path().empty());
    EXPECT_TRUE(in.captures_written().empty());
    EXPECT_FALSE(in.compare().pinned());
    ui->frame();
    EXPECT_EQ(in.frames_rendered(), frames + 4);
    // A folder that is no capture is not pinned; the message names what is missing.
    in.queue(ui::PinCapture{root.parent_path()});
    ui->frame();
    EXPECT_FALSE(in.compare().pinned());
    EXPECT_NE(in.message().find("final.png"), std::string::npos) << in.message();
}

}  // namespace
}  // namespace ds::test
