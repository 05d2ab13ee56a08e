// view --capture DIR on a layer capture (`depthscope layer`): the read-only inspector
// (ui/layer_viewer.h) in a window; no renderer, no scene.
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

#include <cstdio>

#include "app/commands.h"
#include "capture/layer_capture_data.h"
#include "ui/inspector.h"
#include "ui/layer_viewer.h"
#include "ui/presenter.h"
#include "ui/ui_device.h"
#include "ui/window.h"

namespace ds::app {

namespace {

uint64_t run_layer_frames(const Options& o, ui::Window& window, ui::Presenter& presenter,
                          ui::LayerViewer& viewer) {
    uint64_t frames = 0;
    while (!window.should_close() && (o.view_frames == 0 || frames < uint64_t(o.view_frames))) {
        window.poll_events();
        const VkExtent2D fb = window.framebuffer_size();
        ui::Window::Acquired target;
        bool changed = false;
        if (fb.width == 0 || fb.height == 0 || !window.acquire(target, changed)) {
            if (changed) presenter.forget_targets();
            window.wait_events();
            continue;
        }
        if (changed) presenter.forget_targets();
        window.forward_mouse_buttons();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        viewer.draw({target.extent.width, target.extent.height});
        ImGui::Render();
        presenter.present({target.image, target.view, target.extent}, viewer.blit(),
                          ImGui::GetDrawData(), target.acquired, target.rendered);
        window.present(target, changed);
        if (changed) presenter.forget_targets();
        ++frames;
        if (o.view_frames == 0 && !window.take_input()) window.wait_events(0.5);
    }
    return frames;
}

}  // namespace

int run_layer_view(const Options& o) {
    capture::LayerCaptureData data = capture::load_layer_capture(o.capture_in);
    std::printf("depthscope: inspector: layer capture %s (%zu passes with count images)\n",
                o.capture_in.c_str(), data.images.size());
    std::fflush(stdout);
    ui::UiDevice ui_device(o.validate, o.device);
    auto window = std::make_unique<ui::Window>(o.window.width, o.window.height,
                                               "depthscope — layer capture " + o.capture_in);
    window->attach(ui_device.context());
    ImGuiContext* imgui = ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;
    ui::apply_style();
    ImGui_ImplGlfw_InitForVulkan(window->handle(), true);
    window->route_mouse_buttons();
    {
        ui::Presenter presenter(ui_device.context(), window->format());
        ui::LayerViewer viewer(std::move(data));
        const uint64_t frames = run_layer_frames(o, *window, presenter, viewer);
        presenter.wait_idle();
        std::printf("depthscope: %llu frames\n", static_cast<unsigned long long>(frames));
    }
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext(imgui);
    window.reset();
    const uint64_t messages = ui_device.validation_counter()->load();
    ui_device.reset();
    return messages ? 3 : 0;
}

}  // namespace ds::app
