// view (the default command with a display): the inspector in a GLFW window; and the two
// offscreen forms of the same UI, `capture --ui` and `bench --ui` (see cmd_capture/cmd_bench).
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <optional>
#include <tuple>

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

#include "app/capture_source.h"
#include "app/commands.h"
#include "app/exit_code.h"
#include "app/scene_load.h"
#include "app/view_camera.h"
#include "capture/layer_capture_data.h"
#include "renderer/common/error.h"
#include "renderer/common/quoted.h"
#include "renderer/renderer.h"
#include "renderer/scene/loader.h"
#include "ui/config.h"
#include "ui/inspector.h"
#include "ui/presenter.h"
#include "ui/ui_device.h"
#include "ui/window.h"

#ifndef DS_CAPTURE_ROOT
#define DS_CAPTURE_ROOT "captures"
#endif

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

// view --capture DIR: the capture's settings (then --set), scene seen from its camera, and
// final.png for the compare view, all read before any window opens.
struct OpenedCapture {
    std::filesystem::path dir;
    Settings settings;
    scene::Scene scene;
    ui::PinnedCapture pinned;
};

OpenedCapture open_capture(const Options& o) {
    const CaptureSource source = read_capture_source(o.capture_in, o.sets, o.force);
    ui::PinnedCapture pinned = ui::read_pinned_capture(source.dir);
    const capture::Rgba8Image& shot = pinned.final_image;
    if (shot.width != source.info.width || shot.height != source.info.height)
        throw Error(escaped((source.dir / "final.png").string()) + ": " +
                    std::to_string(shot.width) + "x" + std::to_string(shot.height) +
                    ", but report.json says " + std::to_string(source.info.width) + "x" +
                    std::to_string(source.info.height));
    scene::Scene scene = load_captured_scene(source.info, source.settings, o);
    return {source.dir, source.settings, std::move(scene), std::move(pinned)};
}

// Where F12 writes: $DEPTHSCOPE_CAPTURE_DIR, else the captures/ folder `capture` uses.
std::filesystem::path capture_root() {
    const char* dir = std::getenv("DEPTHSCOPE_CAPTURE_DIR");
    return dir && *dir ? std::filesystem::path(dir) : std::filesystem::path(DS_CAPTURE_ROOT);
}

// Where the inspector keeps its state between sessions; all empty without a config folder.
struct ConfigFiles {
    std::filesystem::path dir;
    std::filesystem::path state_file;  // scene and settings
    std::string ini_file;              // ImGui's window layout
};

ConfigFiles config_files() {
    ConfigFiles f;
    f.dir = ui::config_dir();
    f.state_file = f.dir.empty() ? f.dir : f.dir / "settings.ini";
    f.ini_file = f.dir.empty() ? std::string() : (f.dir / "imgui.ini").string();
    return f;
}

// The saved state; lines it could not use are warnings, not errors.
ui::SavedState load_saved_state(const std::filesystem::path& state_file) {
    ui::SavedState saved = state_file.empty() ? ui::SavedState{} : ui::load_state(state_file);
    for (const std::string& line : saved.ignored)
        std::fprintf(stderr, "depthscope: warning: %s: ignored '%s'\n", state_file.c_str(),
                     line.c_str());
    return saved;
}

// A saved scene that no longer loads falls back to the default; a --scene does not.
scene::Scene load_start_scene(const Options& o, const Start& start) {
    try {
        return load_command_scene(o, start.scene, start.settings);
    } catch (const std::exception& e) {
        if (o.scene_given) throw;
        std::fprintf(stderr, "depthscope: warning: saved scene: %s\n", e.what());
        return load_command_scene(o, o.scene, start.settings);
    }
}

// The session's first line: the scene and the settings that differ from the defaults.
void print_session(const scene::Scene& scene, const Settings& settings) {
    std::string changed;
    for (const std::string& name : settings.diff(Settings{}))
        changed += " " + name + "=" + settings.get(name);
    std::printf("depthscope: inspector: %s%s%s\n", scene.name.c_str(), changed.empty() ? "" : ",",
                changed.c_str());
    std::fflush(stdout);
}

// Whether state can be saved: an unusable config folder costs persistence, not the session.
bool prepare_config_dir(const std::filesystem::path& dir) {
    if (dir.empty()) return false;
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir)) {
        std::fprintf(stderr, "depthscope: warning: %s: %s; layout and settings will not be saved\n",
                     dir.c_str(), ec ? ec.message().c_str() : "not a folder");
        return false;
    }
    return true;
}

// The capture pinned for the compare view, and the live frame at its size: the first frame is
// the captured one.
void open_in(ui::Inspector& inspector, OpenedCapture& opened) {
    const capture::Rgba8Image& shot = opened.pinned.final_image;
    std::printf("depthscope: inspector: capture %s (%ux%u)\n", opened.dir.c_str(), shot.width,
                shot.height);
    inspector.pin(std::move(opened.pinned));
    inspector.viewer().compare.match_size = true;
}

// SIGINT and SIGTERM end a session as closing the window does: the loop stops within half a
// second (its longest wait) and the state is saved.
volatile std::sig_atomic_t g_stop = 0;

class StopOnSignal {
  public:
    StopOnSignal() {
        struct sigaction action {};
        action.sa_handler = [](int) { g_stop = 1; };
        sigemptyset(&action.sa_mask);
        sigaction(SIGINT, &action, &old_int_);
        sigaction(SIGTERM, &action, &old_term_);
    }
    ~StopOnSignal() {
        sigaction(SIGINT, &old_int_, nullptr);
        sigaction(SIGTERM, &old_term_, nullptr);
    }
    StopOnSignal(const StopOnSignal&) = delete;
    StopOnSignal& operator=(const StopOnSignal&) = delete;

  private:
    struct sigaction old_int_ {
    }, old_term_{};
};

// $DEPTHSCOPE_PRESENT_LOG: a line each time a presented UI frame shows a newer scene frame
// than the last line, its panels and image drawn from it ("shown 3 800x500 of 800x500 scene
// edges"). The window tests read it to see what reached the screen without input.
class PresentLog {
  public:
    PresentLog() {
        if (const char* path = std::getenv("DEPTHSCOPE_PRESENT_LOG"); path && *path)
            out_.open(path, std::ios::app);
    }
    void presented(const ui::Inspector& in) {
        if (!out_.is_open() || in.frames_rendered() == 0 ||
            in.frames_drawn() != in.frames_rendered())
            return;
        const VkExtent2D full = in.render_size();
        const auto now = std::make_tuple(in.frames_rendered(), in.frame().width, in.frame().height,
                                         full.width, full.height);
        if (now == last_) return;
        last_ = now;
        out_ << "shown " << in.frames_rendered() << ' ' << in.frame().width << 'x'
             << in.frame().height << " of " << full.width << 'x' << full.height << " scene "
             << in.scene().name << std::endl;
    }

  private:
    std::ofstream out_;
    std::tuple<uint64_t, uint32_t, uint32_t, uint32_t, uint32_t> last_{};
};

// Frames until the window closes or --frames are drawn; returns the count drawn. Between UI
// frames the loop sleeps when nothing can change what it draws: after a few frames without
// input, while the inspector is idle it waits for an event (a finished scene frame wakes it
// too), looking at the shader watch twice a second without drawing; while a scene frame
// renders and the camera is still, UI frames come 30 times a second (the "rendering…" mark).
// --frames draws its frames back to back: a scripted run ends when they are drawn.
uint64_t run_frames(const Options& o, ui::Window& window, ui::Presenter& presenter,
                    ui::Inspector& inspector) {
    constexpr int kSettleUiFrames = 3;  // ImGui may need a frame or two after an input
    uint64_t frames = 0;
    size_t written = 0;  // captures reported so far
    int quiet = 0;       // UI frames since the last input
    const bool scripted = o.view_frames != 0;
    const StopOnSignal stop;
    PresentLog log;
    while (!window.should_close() && !g_stop && (!scripted || frames < uint64_t(o.view_frames))) {
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
        for (int key : window.take_pressed_keys()) inspector.key_pressed(key);  // F12
        const bool held_back = window.forward_mouse_buttons();
        ImGui_ImplGlfw_NewFrame();  // input, then the frame
        if (held_back)  // the cursor jumped with a press: this frame only hovers (window.h)
            for (bool& down : ImGui::GetIO().MouseDown) down = false;
        ImDrawData* draw = inspector.run_frame();
        presenter.present({target.image, target.view, target.extent}, inspector.viewer_blit(), draw,
                          target.acquired, target.rendered);
        window.present(target, changed);
        if (changed) presenter.forget_targets();
        log.presented(inspector);
        ++frames;
        for (; written < inspector.captures_written().size(); ++written) {  // F12
            std::printf("depthscope: wrote %s\n", inspector.captures_written()[written].c_str());
            std::fflush(stdout);
        }
        quiet = window.take_input() ? 0 : std::min(quiet + 1, kSettleUiFrames);
        if (scripted || quiet < kSettleUiFrames) continue;
        while (inspector.idle() && !window.should_close() && !g_stop) {
            window.wait_events(0.5);
            if (window.input_pending() || inspector.poll_shader_watch()) break;
        }
        if (inspector.rendering() && !inspector.moving() && !window.input_pending())
            window.wait_events(1.0 / 30.0);
    }
    return frames;
}

// Scene, settings and window layout for the next session; a failed save is a warning. A
// session on a capture keeps the layout only: the capture's state is not the user's.
void save_session(const ConfigFiles& files, const ui::Inspector& inspector, bool state) {
    try {
        if (state)
            ui::save_state(files.state_file, scene_spec(inspector.scene()), inspector.settings());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "depthscope: warning: %s\n", e.what());
    }
    ImGui::SaveIniSettingsToDisk(files.ini_file.c_str());
    // Saved: DestroyContext would save again once the inspector, and with it the workspace's
    // imgui.ini entry (split sizes, open tabs), is gone.
    ImGui::GetIO().IniFilename = nullptr;
}

}  // namespace

bool display_available() {
    const char* x = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x && *x) || (wayland && *wayland);
}

int run_view(const Options& o) {
    // A layer capture has no scene to render again: the read-only inspector.
    if (!o.capture_in.empty() && capture::is_layer_capture(o.capture_in)) return run_layer_view(o);
    const ConfigFiles files = config_files();
    std::optional<OpenedCapture> opened;
    Start start;
    scene::Scene scene;
    if (!o.capture_in.empty()) {  // the capture's state wins over the saved one
        opened = open_capture(o);
        start.settings = opened->settings;
        scene = std::move(opened->scene);
    } else {
        start = start_state(o, load_saved_state(files.state_file));
        scene = load_start_scene(o, start);
        scene.camera = view_camera(o, scene);  // --camera, --look-at: the start camera
    }

    RendererOptions renderer_options;
    renderer_options.validate = o.validate;
    renderer_options.device = o.device;
    Renderer renderer(renderer_options);
    // After the renderer, and destroyed before its shutdown: the swapchain and surface before
    // the UI's device.
    ui::UiDevice ui_device(o.validate, o.device);
    auto window =
        std::make_unique<ui::Window>(o.window.width, o.window.height, "depthscope — " + scene.name);
    window->attach(ui_device.context());
    print_session(scene, start.settings);

    ImGuiContext* imgui = ImGui::CreateContext();
    const bool persist = prepare_config_dir(files.dir);
    ImGui::GetIO().IniFilename = persist ? files.ini_file.c_str() : nullptr;
    ui::apply_style();
    ImGui_ImplGlfw_InitForVulkan(window->handle(), true);
    window->route_mouse_buttons();
    {
        ui::Presenter presenter(ui_device.context(), window->format());
        ui::Inspector::Options options;
        options.capture_root = capture_root();
        options.threaded = true;
        ui::Inspector inspector(renderer, start.settings, std::move(scene), options);
        inspector.worker().on_finished(&ui::Window::wake);
        if (persist) inspector.use_bookmarks(ui::bookmarks_file(files.dir));
        if (opened) open_in(inspector, *opened);
        const uint64_t frames = run_frames(o, *window, presenter, inspector);
        presenter.wait_idle();
        if (persist) save_session(files, inspector, /*state=*/!opened);
        const VkExtent2D last = window->framebuffer_size();
        std::printf(
            "depthscope: %llu frames (window %ux%u), scene frames: %llu posted, %llu shown\n",
            static_cast<unsigned long long>(frames), last.width, last.height,
            static_cast<unsigned long long>(inspector.frames_posted()),
            static_cast<unsigned long long>(inspector.frames_rendered()));
    }
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext(imgui);
    window.reset();
    const std::shared_ptr<const std::atomic<uint64_t>> ui_messages = ui_device.validation_counter();
    ui_device.reset();
    return validation_exit_code(renderer, true, ui_messages->load());
}

}  // namespace ds::app
