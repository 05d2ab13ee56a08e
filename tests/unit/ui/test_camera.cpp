// The inspector's camera actions through its UI: F (and the "frame" button) frames the scene's
// content, "scene camera" returns to the scene's own view. Real lavapipe frames.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "capture/image_writer.h"
#include "tests/unit/ui/inspector_ui.h"

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

}  // namespace
}  // namespace ds::test
