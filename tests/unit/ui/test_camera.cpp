// The inspector's camera actions through its UI: F (and the "frame" button) frames the scene's
// content, "scene camera" returns to the scene's own view; the Camera panel's views: the
// scene's camera nodes, "fit inside", named bookmarks kept in the config folder's
// cameras.json ($DEPTHSCOPE_CONFIG_DIR). Real lavapipe frames.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "capture/image_writer.h"
#include "tests/support/run_process.h"
#include "tests/unit/ui/inspector_ui.h"
#include "ui/config.h"

namespace ds::test {
namespace {

using ui::HeadlessInput;

class InspectorCamera : public InspectorUi {};

// The framing F gives: the content's sphere fits the vertical field of view with 10 % margin.
float framed_distance(const scene::Bounds& content, float yfov) {
    return 1.1f * 0.5f * glm::length(content.extent()) / std::sin(0.5f * yfov);
}

TEST_F(InspectorCamera, FFramesTheContentAndSceneCameraReturns) {
    for (const char* name : {"zfight", "decals", "overdraw", "atrium", "foliage", "edges"}) {
        SCOPED_TRACE(name);
        auto ui = open(name);
        ui::Inspector& in = ui->inspector();
        const scene::Scene& scene = in.scene();
        const scene::Bounds content = scene::content_bounds(scene);
        ASSERT_TRUE(content.valid());
        const ui::ViewerState& v = in.viewer();
        HeadlessInput f;
        f.mouse = glm::vec2(v.x + v.w * 0.5f, v.y + v.h * 0.5f);
        f.keys = {int('F')};
        ui->frame(f);
        const scene::Camera& cam = in.camera();
        const float distance = glm::length(content.center() - cam.position);
        EXPECT_NEAR(distance, framed_distance(content, cam.yfov), 1e-3f * distance);
        EXPECT_GT(glm::dot(glm::normalize(content.center() - cam.position), cam.forward), 0.999f);
        HeadlessInput still;
        still.mouse = f.mouse;
        const std::vector<uint8_t> pixels = ui->frame(still);
        if (const char* dir = std::getenv("DS_TEST_SHOTS"))  // to look at
            capture::write_png_rgba8(std::string(dir) + "/framed_" + name + ".png",
                                     ui->size().width, ui->size().height, pixels);

        in.queue(ui::SceneCamera{});
        ui->frame();
        EXPECT_EQ(in.camera().position, scene.camera.position);
        EXPECT_EQ(in.camera().forward, scene.camera.forward);
    }
}

// Added under a name, the current camera is in cameras.json at once; a new session reads it
// and "go" puts the camera exactly there; another scene has bookmarks of its own; delete
// removes one from the file too.
TEST_F(InspectorCamera, BookmarksPersistReloadAndGoBackExactly) {
    const std::filesystem::path dir =
        std::filesystem::path(DS_TEST_WORK_DIR) / "inspector_bookmarks";
    std::filesystem::remove_all(dir);
    ASSERT_EQ(setenv("DEPTHSCOPE_CONFIG_DIR", dir.c_str(), 1), 0);
    const std::filesystem::path file = ui::bookmarks_file(ui::config_dir());
    EXPECT_EQ(file, dir / "cameras.json");
    scene::Camera saved;
    {
        auto ui = open("atrium");
        ui::Inspector& in = ui->inspector();
        in.use_bookmarks(file);
        in.queue(ui::FitInside{});
        ui->frame();
        saved = in.camera();
        ASSERT_NE(saved, in.scene().camera);
        in.queue(ui::AddBookmark{"  the hall\t"});  // trimmed, a control character a space
        ui->frame();
        ASSERT_EQ(in.scene_bookmarks().size(), 1u);
        EXPECT_EQ(in.scene_bookmarks()[0].name, "the hall");
        EXPECT_EQ(in.bookmarks().error(), "");
        in.queue(ui::SceneCamera{});
        ui->frame();
        EXPECT_EQ(in.camera(), in.scene().camera);
    }
    ASSERT_TRUE(std::filesystem::is_regular_file(file));
    const auto json = nlohmann::json::parse(read_file(file));
    EXPECT_EQ(json["scenes"]["builtin:atrium"][0]["name"], "the hall");

    auto ui = open("atrium");
    ui::Inspector& in = ui->inspector();
    in.use_bookmarks(file);
    ASSERT_EQ(in.scene_bookmarks().size(), 1u);
    in.queue(ui::GoToBookmark{"the hall"});
    ui->frame();
    EXPECT_EQ(in.camera(), saved);  // bit for bit, through the file
    in.queue(ui::LoadScene{"edges"});
    ui->frame();
    EXPECT_TRUE(in.scene_bookmarks().empty());
    in.queue(ui::LoadScene{"atrium"});
    in.queue(ui::DeleteBookmark{"the hall"});
    ui->frame();
    EXPECT_TRUE(in.scene_bookmarks().empty());
    EXPECT_TRUE(ui::CameraBookmarks(file).of("builtin:atrium").empty());
    unsetenv("DEPTHSCOPE_CONFIG_DIR");
    EXPECT_EQ(renderer_->validation_message_count(), 0u);
}

// A cameras.json that is not depthscope's bookmarks is left as it is and says so.
TEST(CameraBookmarks, AForeignFileIsNeverOverwritten) {
    const std::filesystem::path file =
        std::filesystem::path(DS_TEST_WORK_DIR) / "foreign_cameras.json";
    std::ofstream(file) << "not bookmarks\n";
    ui::CameraBookmarks bookmarks(file);
    EXPECT_NE(bookmarks.error().find("not depthscope's camera bookmarks"), std::string::npos);
    bookmarks.put("builtin:atrium", "a", scene::Camera{});
    EXPECT_EQ(read_file(file), "not bookmarks\n");
    ASSERT_NE(bookmarks.find("builtin:atrium", "a"), nullptr);  // for this session
}

// "fit inside": the camera inside the scene's bounds, looking along their longest horizontal
// axis, the field of view kept; a camera node's "go" is that node's camera.
TEST_F(InspectorCamera, FitInsidePutsTheCameraInsideTheBounds) {
    for (const char* name : {"atrium", "edges", "foliage"}) {
        SCOPED_TRACE(name);
        auto ui = open(name);
        ui::Inspector& in = ui->inspector();
        const scene::Bounds& b = in.scene().bounds;
        const float yfov = in.camera().yfov;
        in.queue(ui::FitInside{});
        const std::vector<uint8_t> pixels = ui->frame();
        if (const char* shots = std::getenv("DS_TEST_SHOTS"))
            capture::write_png_rgba8(std::string(shots) + "/inside_" + name + ".png",
                                     ui->size().width, ui->size().height, pixels);
        const scene::Camera& c = in.camera();
        for (int axis = 0; axis < 3; ++axis) {
            EXPECT_GT(c.position[axis], b.min[axis]) << axis;
            EXPECT_LT(c.position[axis], b.max[axis]) << axis;
        }
        const glm::vec3 e = b.extent();
        EXPECT_EQ(std::fabs(e.x >= e.z ? c.forward.x : c.forward.z), 1.0f);
        EXPECT_EQ(c.yfov, yfov);
        in.queue(ui::GoToCamera{0});
        ui->frame();
        ASSERT_FALSE(in.scene().cameras.empty());
        EXPECT_EQ(in.camera(), *in.scene().cameras[0].camera);
    }
    EXPECT_EQ(renderer_->validation_message_count(), 0u);
}

}  // namespace
}  // namespace ds::test
