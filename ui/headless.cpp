#include "ui/headless.h"

#include <algorithm>

#include <imgui.h>

#include "renderer/common/error.h"

namespace ds::ui {

HeadlessUi::HeadlessUi(Renderer& renderer, Settings settings, scene::Scene scene, VkExtent2D size,
                       std::optional<VkExtent2D> render_size,
                       const std::optional<vk::ContextOptions>& ui_device)
    : size_(size) {
    if (size.width == 0 || size.height == 0) throw Error("ui: empty size");
    imgui_ = ImGui::CreateContext();
    ImGui::SetCurrentContext(imgui_);
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // offscreen frames do not read or write the user's layout
    io.DisplaySize = ImVec2(float(size.width), float(size.height));
    apply_style();
    try {
        if (ui_device) ui_device_ = std::make_unique<vk::Context>(*ui_device);
        presenter_ = std::make_unique<Presenter>(ui_device_ ? *ui_device_ : renderer.context(),
                                                 Presenter::kOffscreenFormat);
        inspector_ =
            std::make_unique<Inspector>(renderer, std::move(settings), std::move(scene),
                                        Inspector::Options{.fallback_width = size.width,
                                                           .fallback_height = size.height,
                                                           .watch_shaders = false,
                                                           .render_size = render_size,
                                                           .threaded = ui_device_ != nullptr});
    } catch (...) {
        presenter_.reset();
        ui_device_.reset();
        ImGui::DestroyContext(imgui_);
        throw;
    }
}

HeadlessUi::~HeadlessUi() {
    ImGui::SetCurrentContext(imgui_);
    presenter_.reset();
    inspector_.reset();
    ui_device_.reset();
    ImGui::DestroyContext(imgui_);
}

uint64_t HeadlessUi::ui_validation_messages() const {
    return ui_device_ ? ui_device_->validation_message_count() : 0;
}

std::vector<uint8_t> HeadlessUi::frame(const HeadlessInput& input) {
    ImGui::SetCurrentContext(imgui_);
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(float(size_.width), float(size_.height));
    io.DeltaTime = std::max(input.dt, 1e-4f);
    io.MousePos = input.mouse ? ImVec2(input.mouse->x, input.mouse->y) : ImVec2(-FLT_MAX, -FLT_MAX);
    io.MouseDown[0] = input.left;
    io.MouseDown[1] = input.right;
    io.MouseDown[2] = input.middle;
    io.MouseWheel = input.wheel;
    io.KeyCtrl = input.ctrl;
    io.KeyShift = input.shift;
    std::fill(std::begin(io.KeysDown), std::end(io.KeysDown), false);
    for (int k : input.keys)
        if (k >= 0 && k < int(IM_ARRAYSIZE(io.KeysDown))) io.KeysDown[k] = true;
    for (int k : input.pressed) inspector_->key_pressed(k);

    ImDrawData* draw = inspector_->run_frame();
    return presenter_->render_offscreen(size_, inspector_->viewer_blit(), draw, &stats_);
}

}  // namespace ds::ui
