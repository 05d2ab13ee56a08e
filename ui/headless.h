#pragma once
// The inspector without a window: an ImGui context with no platform backend (the caller feeds
// the input), composited by the same Presenter onto an offscreen image. `capture --ui`,
// `bench --ui` and the UI tests use it; the window (ui/window.h) differs only in where input
// comes from and where the pixels go.
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <vulkan/vulkan.h>
#include <glm/glm.hpp>

#include "renderer/vk/context.h"
#include "ui/inspector.h"
#include "ui/presenter.h"

struct ImGuiContext;

namespace ds::ui {

// One frame's input, in framebuffer pixels.
struct HeadlessInput {
    std::optional<glm::vec2> mouse;  // none: the cursor is outside the window
    bool left = false, right = false, middle = false;
    float wheel = 0.0f;
    bool ctrl = false, shift = false;
    std::vector<int> keys;  // held, by ImGui 1.86 key index (GLFW codes: ASCII for letters)
    float dt = 1.0f / 60.0f;
    std::vector<int> pressed;  // pressed since the last frame, as the window's callback reports
};

class HeadlessUi {
  public:
    // `render_size`: the scene frame's size (bench --ui: the same as without the UI); none:
    // the viewer's area times render_scale, as in the window.
    // `ui_device`: the window's arrangement (tests): the UI on a device of its own made with
    // these options, scene frames on the inspector's render thread; none: one device, a scene
    // frame rendered inside every frame().
    HeadlessUi(Renderer& renderer, Settings settings, scene::Scene scene, VkExtent2D size,
               std::optional<VkExtent2D> render_size = std::nullopt,
               const std::optional<vk::ContextOptions>& ui_device = std::nullopt);
    ~HeadlessUi();
    HeadlessUi(const HeadlessUi&) = delete;
    HeadlessUi& operator=(const HeadlessUi&) = delete;

    // One UI frame: ImGui frame with `input`, panels, actions, a rendered scene frame, the
    // composite read back (RGBA8, row 0 = top, size()).
    std::vector<uint8_t> frame(const HeadlessInput& input = {});

    Inspector& inspector() { return *inspector_; }
    VkExtent2D size() const { return size_; }
    const UiFrameStats& last_stats() const { return stats_; }
    // Validation messages of the UI's own device (0 without one).
    uint64_t ui_validation_messages() const;

  private:
    ImGuiContext* imgui_ = nullptr;
    VkExtent2D size_;
    std::unique_ptr<vk::Context> ui_device_;
    std::unique_ptr<Presenter> presenter_;
    std::unique_ptr<Inspector> inspector_;
    UiFrameStats stats_;
};

}  // namespace ds::ui
