#pragma once
// What the inspector's offscreen tests share: a HeadlessUi on the shared renderer (lavapipe
// here, validation on), laid out by one frame, and where a viewer texel is on the screen.
#include <cstdint>
#include <memory>
#include <string>

#include <glm/glm.hpp>

#include "renderer/scene/loader.h"
#include "tests/gpu/passes/shared_renderer.h"
#include "ui/headless.h"

namespace ds::test {

class InspectorUi : public SharedRenderer {
  protected:
    std::unique_ptr<ui::HeadlessUi> open(const std::string& scene_name, Settings settings = {},
                                         VkExtent2D size = {960, 540}) {
        scene::Scene scene = scene::load_scene(scene_name, settings);
        auto ui = std::make_unique<ui::HeadlessUi>(*renderer_, settings, std::move(scene), size);
        ui->frame();  // lays the panels out: the viewer's area is known from here on
        return ui;
    }
    // The framebuffer position of texel (x, y)'s centre in the viewer.
    static glm::vec2 screen_of(const ui::HeadlessUi& ui, uint32_t x, uint32_t y) {
        const ui::ViewerBlit b = const_cast<ui::HeadlessUi&>(ui).inspector().viewer_blit();
        const float zoom = b.dst_w / b.src_w;
        return {b.dst_x + (float(x) + 0.5f - b.src_x) * zoom,
                b.dst_y + (float(y) + 0.5f - b.src_y) * zoom};
    }
};

}  // namespace ds::test
