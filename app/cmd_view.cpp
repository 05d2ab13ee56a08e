// view (the default command with a display): the inspector in a GLFW window; and the two
// offscreen forms of the same UI, `capture --ui` and `bench --ui` (see cmd_capture/cmd_bench).
#include <cstdio>
#include <cstdlib>

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

#include "app/commands.h"
#include "app/exit_code.h"
#include "renderer/common/error.h"
#include "renderer/renderer.h"
#include "renderer/scene/loader.h"
#include "ui/config.h"
#include "ui/inspector.h"
#include "ui/presenter.h"
#include "ui/window.h"

namespace ds::app {
namespace {

// Scene and settings: the saved state first, the command line over it.
struct Start {
    std::string scene;
    Settings settings;
};

Start start_state(const Options& o, const ui::SavedState& saved) {
    Start s;
    s.scene = o.scene_given || saved.scene.empty() ? o.scene : saved.scene;
    for (const std::string& line : saved.sets) s.settings.apply(line);
    for (const std::string& line : o.sets) s.settings.apply(line);
    return s;
}

std::string scene_spec(const scene::Scene& scene) {
    const std::string prefix = "builtin:";
    return scene.source.rfind(prefix, 0) == 0 ? scene.source.substr(prefix.size()) : scene.source;
}

}  // namespace

bool display_available() {
    const char* x = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x && *x) || (wayland && *wayland);
}

int run_view(const Options& o) {
    const std::filesystem::path dir = ui::config_dir();
    const std::filesystem::path state_file = dir.empty() ? dir : dir / "settings.ini";
    const std::string ini_file = dir.empty() ? std::string() : (dir / "imgui.ini").string();
    const ui::SavedState saved = state_file.empty() ? ui::SavedState{} : ui::load_state(state_file);
    for (const std::string& line : saved.ignored)
        std::fprintf(stderr, "depthscope: warning: %s: ignored '%s'\n", state_file.c_str(),
                     line.c_str());
    Start start = start_state(o, saved);
    // A saved scene that no longer loads falls back to the default; a --scene does not.
    scene::Scene scene = [&] {
        try {
            return scene::load_scene(start.scene, start.settings);
        } catch (const std::exception& e) {
            if (o.scene_given) throw;
            std::fprintf(stderr, "depthscope: warning: saved scene: %s\n", e.what());
            return scene::load_scene(o.scene, start.settings);
        }
    }();

    RendererOptions renderer_options;
    renderer_options.validate = o.validate;
    renderer_options.device = o.device;
    renderer_options.instance_extensions = ui::Window::instance_extensions();
    renderer_options.swapchain = true;
    Renderer renderer(renderer_options);
    // After the renderer, so it goes first: the swapchain and surface before the device.
    ui::Window window(o.window.width, o.window.height, "depthscope — " + scene.name);
    window.attach(renderer.context());

    {
        std::string changed;
        for (const std::string& name : start.settings.diff(Settings{}))
            changed += " " + name + "=" + start.settings.get(name);
        std::printf("depthscope: inspector: %s%s%s\n", scene.name.c_str(),
                    changed.empty() ? "" : ",", changed.c_str());
        std::fflush(stdout);
    }
    ImGuiContext* imgui = ImGui::CreateContext();
    // An unusable config folder costs persistence, not the session.
    bool persist = !dir.empty();
    if (persist) {
        std::error_code ec;
        std::filesystem::create_directories(dir, ec);
        if (ec || !std::filesystem::is_directory(dir)) {
            std::fprintf(stderr,
                         "depthscope: warning: %s: %s; layout and settings will not be saved\n",
                         dir.c_str(), ec ? ec.message().c_str() : "not a folder");
            persist = false;
        }
    }
    ImGui::GetIO().IniFilename = persist ? ini_file.c_str() : nullptr;
    ui::apply_style();
    ImGui_ImplGlfw_InitForVulkan(window.handle(), true);
    {
        ui::Presenter presenter(renderer.context(), window.format());
        ui::Inspector inspector(renderer, start.settings, std::move(scene), {});
        uint64_t frames = 0;
        while (!window.should_close() && (o.view_frames == 0 || frames < uint64_t(o.view_frames))) {
            window.poll_events();
            const VkExtent2D fb = window.framebuffer_size();
            if (fb.width == 0 || fb.height == 0) {  // minimised: nothing to draw
                window.wait_events();
                continue;
            }
            ui::Window::Acquired target;
            bool changed = false;
            if (!window.acquire(target, changed)) {
                if (changed) presenter.forget_targets();
                window.wait_events();  // no swapchain to draw into yet
                continue;
            }
            if (changed) presenter.forget_targets();
            ImGui_ImplGlfw_NewFrame();  // input, then the frame
            ImDrawData* draw = inspector.run_frame();
            presenter.present({target.image, target.view, target.extent}, inspector.viewer_blit(),
                              draw, target.acquired, target.rendered);
            window.present(target, changed);
            if (changed) presenter.forget_targets();
            ++frames;
        }
        presenter.wait_idle();
        if (persist) {
            try {
                ui::save_state(state_file, scene_spec(inspector.scene()), inspector.settings());
            } catch (const std::exception& e) {
                std::fprintf(stderr, "depthscope: warning: %s\n", e.what());
            }
        }
        if (persist) ImGui::SaveIniSettingsToDisk(ini_file.c_str());
        const VkExtent2D last = window.framebuffer_size();
        std::printf("depthscope: %llu frames (window %ux%u)\n",
                    static_cast<unsigned long long>(frames), last.width, last.height);
    }
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext(imgui);
    return validation_exit_code(renderer);
}

}  // namespace ds::app
