#pragma once
// The inspector's model and one UI frame's logic, without Vulkan: the settings, the scene, the
// camera, what the user selected, the last FrameResult and its decoded view. Each frame, once
// the platform has fed ImGui its input, run_frame() runs
//   ImGui::NewFrame();
//   draw();          // the panels (ui/panels): read this state, return actions
//   update();        // apply the actions and the camera input, post a scene frame if
//                    // needed, take a finished one, decode
//   ImGui::Render();
// and ui::Presenter draws viewer_blit() and the returned draw data.
// Scene frames render through a RenderWorker (ui/render_worker.h): on a render thread
// (Options::threaded, the window: the UI runs at display rate and renders only on change, see
// inspector_frames.cpp) or inside update() (offscreen UIs: a new frame every UI frame).
// Tests drive it the same way, or call apply() with the actions a panel would return.
#include <array>
#include <chrono>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <future>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "capture/advice.h"
#include "capture/diagnose/finding.h"
#include "renderer/device_info.h"
#include "renderer/passes/msaa_samples.h"
#include "renderer/passes/pixel_history.h"
#include "renderer/renderer.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings.h"
#include "renderer/view/decode.h"
#include "renderer/view/readout.h"
#include "ui/camera_bookmarks.h"
#include "ui/camera_controller.h"
#include "ui/compare.h"
#include "ui/panels/workspace.h"
#include "ui/render_worker.h"
#include "ui/sample_view.h"
#include "ui/shader_watch.h"
#include "ui/tuning.h"
#include "ui/view_composer.h"
#include "ui/viewer_blit.h"

struct ImDrawData;

namespace ds::ui {

// depthscope's ImGui look (window and offscreen alike).
void apply_style();

// What panels ask for; Inspector::apply() carries it out.
struct SetSetting {
    std::string name, value;
};
struct SelectResource {
    std::string name;
};
struct SelectPass {
    std::string name;
};
struct LoadScene {
    std::string name_or_path;  // a built-in name or a .gltf / .glb path
};
struct ReloadShaders {};
struct SetAutoReload {
    bool on = true;
};
struct ResetSettings {};
// The Advisor panel's "measure": the prepass advisor over the current camera and settings.
struct MeasureAdvice {};
// Back to the scene's own camera (the file's, or the framed view of a scene without one; the
// command line's --camera or --look-at when it chose one).
struct SceneCamera {};
// The Camera panel: one of the scene's camera nodes (scene().cameras[index], perspective); the
// view "fit inside" finds for interiors (scene/fit_inside.h); named bookmarks of this scene's
// views (ui/camera_bookmarks.h): the current camera added under a name (replacing one of that
// name), gone to, deleted.
struct GoToCamera {
    size_t index = 0;
};
struct FitInside {};
struct AddBookmark {
    std::string name;
};
struct GoToBookmark {
    std::string name;
};
struct DeleteBookmark {
    std::string name;
};
// The Diagnose button: every detector that applies, on the current view, off the UI thread
// (capture/diagnose/diagnose_run.h); its findings list in the Diagnose panel.
struct Diagnose {};
// A finding of the diagnosis selected (-1: none): its pixels are highlighted over the image
// while the view is the one diagnosed, and the panel with its details opens.
struct SelectFinding {
    int index = -1;
};
// The Overlays panel's list edits (opacity and visibility it writes directly: view state).
struct AddOverlay {
    std::string resource;  // an image of the frame or a derived view ("forward_wasted")
};
struct RemoveOverlay {
    size_t index = 0;
};
struct MoveOverlay {
    size_t index = 0;
    int by = 0;  // -1: drawn earlier (under), +1: later (over)
};
// A click on the image in pick mode (or with Alt): the pixel history of render pixel (x, y)
// with the current camera, size and settings.
struct PickPixel {
    uint32_t x = 0, y = 0;
};
// F12 or the Capture button: a capture of the current frame (camera, settings, render size)
// into the capture root, through the live renderer; pinned for the compare view afterwards.
// Written two UI frames later, once "capturing…" has been presented: the UI waits meanwhile.
struct CaptureFrame {};
// The compare view's capture: a capture folder's final.png (an empty path unpins).
struct PinCapture {
    std::filesystem::path dir;
};
using Action =
    std::variant<SetSetting, SelectResource, SelectPass, LoadScene, ReloadShaders, SetAutoReload,
                 ResetSettings, MeasureAdvice, SceneCamera, GoToCamera, FitInside, AddBookmark,
                 GoToBookmark, DeleteBookmark, Diagnose, SelectFinding, AddOverlay, RemoveOverlay,
                 MoveOverlay, PickPixel, CaptureFrame, PinCapture, Tune>;

enum class MouseTarget : uint8_t { Camera, Image, Pick };

// An image drawn over the shown one, decoded (counts as a heat map) and blended with
// `opacity` where its value is not 0.
struct Overlay {
    std::string resource;
    float opacity = 0.5f;
    bool visible = true;
};

// The viewer's state: what is shown and how (panels change it directly: it is view state).
struct ViewerState {
    std::string resource = "final";
    uint32_t sample = 0;
    view::ViewParams params;
    float zoom = 1.0f;             // screen pixels per image texel
    glm::vec2 centre{0.5f, 0.5f};  // the image point at the viewport's centre (0..1)
    MouseTarget mouse = MouseTarget::Camera;
    int zfight_pair = -1;  // the Depth panel's selected pair: the zfight view shows only it
    int draw = -1;         // the Draws panel's selected draw group: its pixels stay, the rest dims
    int finding = -1;      // the Diagnose panel's selected finding: its pixels highlighted
    std::vector<Overlay> overlays;   // blended in order: the last on top
    bool shared_count_scale = true;  // a pass's count images share one heat scale and legend
    CompareState compare;            // the live frame against a pinned capture
    // Zoomed in to kSampleViewZoom or more: draw each pixel's samples (ui/sample_view.h).
    bool sample_view = true;
    // Filled by the viewer panel.
    float x = 0, y = 0, w = 0, h = 0;  // the image area, in framebuffer pixels
    std::optional<view::Readout> hover;
    std::string hover_overlays;  // the visible overlays' values there ("" without)
};

// Per-pass GPU ms of the last kHistory frames.
struct PassHistory {
    static constexpr size_t kHistory = 120;
    std::map<std::string, std::deque<double>> pass_ms;
    std::deque<double> frame_ms;
    void add(const FrameResult& frame);
    double median(const std::string& pass) const;
};

struct SceneSummary {
    std::string name, source;
    size_t draw_groups = 0, instances = 0, meshes = 0;
    uint64_t triangles = 0;
    size_t opaque = 0, masked = 0, blend = 0;  // materials by alpha mode
    struct Masked {
        std::string name;
        float own_cutoff = 0.5f;  // the glTF material's alphaCutoff
    };
    std::vector<Masked> masked_materials;
};

class Inspector {
  public:
    struct Options {
        uint32_t fallback_width = 1280, fallback_height = 720;  // before the first layout
        bool watch_shaders = true;
        std::optional<VkExtent2D> render_size;            // fixed scene size (bench --ui)
        std::filesystem::path capture_root = "captures";  // where F12 writes (a folder each)
        // Scene frames on a render thread, only when something changed (the window); false:
        // one rendered in every update() (capture --ui, bench --ui, frame-by-frame tests).
        bool threaded = false;
    };
    Inspector(Renderer& renderer, Settings settings, scene::Scene scene, Options options);
    ~Inspector();  // waits for a diagnosis in flight (it holds the renderer)
    Inspector(const Inspector&) = delete;
    Inspector& operator=(const Inspector&) = delete;

    ImDrawData* run_frame();  // one UI frame, as above
    void draw();              // inside an ImGui frame
    void update();            // after draw(): actions, camera, one rendered frame, decode
    void apply(const Action& action);
    void queue(Action action) { pending_.push_back(std::move(action)); }
    // A key press, by GLFW key code, from the window's key callback (or HeadlessUi): F12
    // captures. Presses come from the driver, not ImGui 1.86, which sees only keys held down
    // at a frame's start.
    static constexpr int kCaptureKey = 301;  // GLFW_KEY_F12
    void key_pressed(int key);

    // What the presenter draws under ImGui.
    ViewerBlit viewer_blit() const;

    // The render thread (tests slow it down; the window wakes on its frames).
    RenderWorker& worker() { return *worker_; }
    // Nothing to do until input arrives: no frame rendering or waiting, the camera at rest, no
    // capture pending, not continuous. The window then sleeps until an event.
    bool idle() const;
    // The shader watch (auto reload on): true when the shaders changed, a reload then queued.
    // Cheap: the idle window asks it at every wake-up instead of drawing a UI frame.
    bool poll_shader_watch();
    // A scene frame is rendering (or waiting), or a diagnosis runs: the viewer marks
    // "rendering… N ms" (or "diagnosing… N s"), the window draws the UI at 30 Hz meanwhile.
    bool rendering() const { return worker_->busy() || diagnosing() || tuning_.running(); }
    double rendering_ms() const { return worker_->in_flight_ms(); }
    // Frames posted to the worker so far (each UI frame in synchronous mode).
    uint64_t frames_posted() const { return frames_posted_; }
    // The camera moved within the last kMotionHold: frames render at motion_scale.
    bool moving() const;

    // State, for the panels and tests.
    const DeviceInfo& device() const { return device_; }
    const Settings& settings() const { return settings_; }
    const scene::Scene& scene() const { return scene_; }
    const SceneSummary& scene_summary() const { return summary_; }
    const FrameResult& frame() const { return frame_; }
    const view::DecodedView& view() const { return view_; }
    // The image the viewer shows (read back or derived); none when the frame lacks it.
    const InspectedImage* shown() const { return shown_; }
    // What can be shown or overlaid (image resources and derived views), in list order.
    std::vector<std::string> viewable() const { return ViewComposer::viewable(frame_.resources); }
    const ViewComposer& composer() const { return composer_; }
    const PassHistory& history() const { return history_; }
    ViewerState& viewer() { return viewer_; }
    const ViewerState& viewer() const { return viewer_; }
    const std::string& selected_pass() const { return selected_pass_; }
    const std::string& message() const { return message_; }  // last error, "" = none
    const std::string& shader_status() const { return shader_status_; }
    bool shader_error() const { return shader_error_; }
    bool auto_reload() const { return auto_reload_; }
    uint64_t frames_rendered() const { return frames_rendered_; }
    uint64_t frames_drawn() const { return frames_drawn_; }  // the newest the panels drew
    // The last MeasureAdvice's result (none until measured), what it measured ("overdraw at
    // 960x540") and its error, if it failed.
    const std::optional<capture::Advice>& advice() const { return advice_; }
    const std::string& advice_label() const { return advice_label_; }
    const std::string& advice_error() const { return advice_error_; }
    // The last Diagnose's result (none until one finished), its error, and whether one runs
    // now (seconds so far). A diagnosis is of one view: current() says whether the camera,
    // settings and render size are still the ones it diagnosed (its pixels are shown only
    // then); a new scene drops it.
    const std::optional<diagnose::Diagnosis>& diagnosis() const { return diagnosis_; }
    const std::string& diagnosis_error() const { return diagnosis_error_; }
    bool diagnosing() const { return diagnosis_future_.valid(); }
    uint64_t diagnoses_started() const { return diagnoses_started_; }
    double diagnosing_seconds() const;
    bool diagnosis_current() const;
    // The Tuning panel's runs (ui/tuning.h): tune msaa / alpha on the current view.
    const Tuning& tuning() const { return tuning_; }
    // The selected finding's pixels as a keep mask at the frame's size; empty when none is
    // selected, it covers none, or the view is not the one diagnosed.
    std::vector<uint8_t> selected_finding_pixels() const;
    // The last PickPixel's history (none until picked), the frame's depth planes for its
    // linear depths, what it rendered ("atrium at 960x540") and its error, if it failed.
    const std::optional<PixelHistory>& pixel_history() const { return pixel_history_; }
    const std::optional<DepthResult>& pixel_depth() const { return pixel_depth_; }
    const std::string& pixel_label() const { return pixel_label_; }
    const std::string& pixel_error() const { return pixel_error_; }
    uint64_t pixel_picks() const { return pixel_picks_; }  // PickPixel actions applied so far
    // The picked pixel's samples, read by the pick's frame (none before a pick).
    const std::optional<MsaaSamples>& pixel_samples() const { return pixel_samples_; }
    // The sample view: on and zoomed in far enough (the next frame asks for samples).
    bool sample_view_wanted() const {
        return viewer_.sample_view && viewer_.zoom >= kSampleViewZoom;
    }
    // The shown frame's samples when it has them (zoomed in), else null.
    const MsaaSamples* shown_samples() const;
    // Texel (x, y)'s samples in the shown frame (the hover list); none outside what was read.
    std::optional<PixelSampleList> sample_list_at(uint32_t x, uint32_t y) const;
    // The picked pixel's prepass coverage per fragment (msaa > 1; empty otherwise).
    std::vector<CoverageRow> pixel_coverage() const;
    // Renderer::describe_surface (safe from the UI thread: see RenderWorker).
    std::optional<SurfaceInfo> describe_surface(uint32_t id) const;
    const scene::Camera& camera() const { return camera_.camera(); }
    // This scene's camera bookmarks (and their file's trouble: bookmarks().error()).
    const std::vector<CameraBookmark>& scene_bookmarks() const {
        return bookmarks_.of(bookmark_key(scene_));
    }
    const CameraBookmarks& bookmarks() const { return bookmarks_; }
    // Reads and from now on keeps the bookmarks in `file` (the window: the config folder's
    // cameras.json, ui/config.h); until then they last the session (capture --ui, bench --ui).
    void use_bookmarks(const std::filesystem::path& file) { bookmarks_ = CameraBookmarks(file); }
    CameraInput& camera_input() { return camera_input_; }
    // The render size the next frame uses: the viewer's area times render_scale (the pinned
    // capture's size with compare.match_size).
    VkExtent2D render_size() const;
    // Captures (F12): the folder the last one wrote ("" none yet) and its error ("" none),
    // every folder written this session, the compare view.
    const std::filesystem::path& capture_path() const { return capture_path_; }
    const std::string& capture_error() const { return capture_error_; }
    bool capturing() const { return pending_capture_.has_value(); }  // asked, not yet written
    const std::vector<std::filesystem::path>& captures_written() const { return captures_; }
    const CaptureCompare& compare() const { return compare_; }
    void set_capture_root(std::filesystem::path root) { options_.capture_root = std::move(root); }
    // Pins a capture read beforehand (view --capture); PinCapture reads one itself.
    void pin(PinnedCapture capture) { compare_.pin(std::move(capture)); }
    // Hover readout of the shown resource at image texel (x, y).
    std::optional<view::Readout> readout_at(uint32_t x, uint32_t y) const;
    std::vector<uint8_t> selected_pair_pixels() const;
    // The selected draw's pixels (surface_id's winner in its group) as a keep mask; empty
    // when no draw is selected or the frame did not count draws.
    std::vector<uint8_t> selected_draw_pixels() const;
    std::string zfight_text(uint32_t x, uint32_t y) const;
    // The visible overlays' values at texel (x, y): "forward_counts: 3 fragments | ...".
    std::string overlay_text(uint32_t x, uint32_t y) const;

    // Panel state that outlives a frame (text fields).
    struct PanelState {
        std::array<char, 512> scene_path{};
        std::array<char, 128> draw_filter{};    // the Draws panel's filter (mesh/material/node)
        std::array<char, 512> pin_path{};       // the Compare panel's capture folder field
        std::array<char, 128> bookmark_name{};  // the Camera panel's name for a new bookmark
        std::vector<size_t> draw_rows;          // the Draws panel's rows as last drawn
        uint64_t pixel_picks_shown = 0;         // the Pixel panel opens on a new pick
        uint64_t diagnoses_shown = 0;           // the Diagnose panel opens on a new diagnosis
        int tune_cost = 0;                      // the Tuning panel's cost: 0 fragments, 1 ms
    };
    PanelState& panel_state() const { return panel_state_; }
    // The panels' layout: regions, tabs, splits (ui/panels/workspace.h); workspace().select(
    // "Pixel") shows a panel's tab from the next frame on.
    Workspace& workspace() { return workspace_; }
    const Workspace& workspace() const { return workspace_; }

  private:
    static constexpr const char* kZfightImage = "zfight";         // a heat map over the frame
    static constexpr std::chrono::milliseconds kMotionHold{200};  // "moving" after input

    void set_scene(scene::Scene scene);
    // Applies `changed` (rebuilding a built-in scene whose knobs changed); throws, changing
    // nothing, when the rebuild fails.
    void change_settings(const Settings& changed);
    // apply()'s steps that may fail: the message says why and nothing changes.
    void set_setting(const std::string& name, const std::string& value);
    void set_settings_or_say(const Settings& changed);
    void load_named_scene(const std::string& name_or_path);
    void reload_shaders();
    // inspector_frames.cpp: what the next scene frame is, whether it differs from the last one
    // posted, taking a finished frame, decoding the view when it or the frame changed.
    FrameJob next_job() const;
    void schedule();
    bool collect();  // false: nothing finished, or it failed
    void refresh_view();
    void measure_advice();
    // inspector_diagnose.cpp
    struct DiagnosedView {
        scene::Camera camera;
        Settings settings;
        VkExtent2D size{};
    };
    void start_diagnosis();
    void collect_diagnosis();          // a finished diagnosis, if any (update())
    void start_tuning(const Tune& t);  // inspector_tuning.cpp
    void select_finding(int index);
    // A selected Z-fight finding's pair, selected in the Depth panel once a frame has it.
    void select_finding_pair();
    void pick_pixel(const PickPixel& pick);
    // inspector_state.cpp: what is derived from a scene or a frame follows it.
    struct Pick {
        uint32_t x = 0, y = 0;  // at the full render size
        VkExtent2D size{};
    };
    void render_pick(const Pick& pick);  // the history of `pick`, under the current settings
    void repick();                       // settings changed: the same pixel again, if picked
    void drop_pick();
    void drop_pick_of_other_size();  // the render size changed: the pick names another point
    void forget_scene_state();       // a new scene: picks, selections, advice, the compare pin
    // A new frame landed: the selected Z-fight pair is found again by its surfaces (-1 gone).
    void follow_selected_pair(const FrameResult& previous);
    // inspector_capture.cpp
    struct PendingCapture {
        scene::Camera camera;  // as the frame shown when it was asked for
        VkExtent2D size{};
        uint64_t update = 0;  // the update() that asked
    };
    void request_capture();
    void capture_when_shown();
    void capture_frame(const PendingCapture& request);
    void pin_capture(const std::filesystem::path& dir);
    // inspector_camera.cpp: the Camera panel's actions.
    void go_to_camera(size_t index);
    void fit_inside();
    void add_bookmark(const std::string& name);

    Renderer& renderer_;  // through worker_ (exclusive()) once it exists
    DeviceInfo device_;   // what the panels say of the device's counters
    Settings settings_;
    Settings last_good_;  // the settings of the last frame that rendered
    scene::Scene scene_;
    SceneSummary summary_;
    Options options_;
    CameraController camera_;
    CameraBookmarks bookmarks_;
    CameraInput camera_input_;
    ViewerState viewer_;
    std::string selected_pass_;
    std::vector<Action> pending_;
    FrameResult frame_;
    view::DecodedView view_;
    ViewComposer composer_;
    const InspectedImage* shown_ = nullptr;  // in frame_ or composer_
    PassHistory history_;
    std::string message_;
    std::string shader_status_ = "shaders compiled";
    bool shader_error_ = false;
    bool auto_reload_ = true;
    ShaderWatch watch_;
    uint64_t frames_rendered_ = 0;
    std::optional<capture::Advice> advice_;
    std::string advice_label_, advice_error_;
    std::optional<diagnose::Diagnosis> diagnosis_;
    std::optional<DiagnosedView> diagnosed_view_;
    std::string diagnosis_error_;
    std::future<diagnose::Diagnosis> diagnosis_future_;  // a diagnosis in flight
    DiagnosedView diagnosing_view_;                      // what it diagnoses
    std::chrono::steady_clock::time_point diagnosis_started_{};
    uint64_t diagnoses_started_ = 0;
    std::vector<diagnose::FindingSurface> finding_pair_;  // to select in the Depth panel
    Tuning tuning_;
    std::optional<PixelHistory> pixel_history_;
    std::optional<DepthResult> pixel_depth_;
    std::optional<MsaaSamples> pixel_samples_;
    std::string pixel_label_, pixel_error_;
    std::optional<Pick> pick_;  // the last pick that rendered
    uint64_t pixel_picks_ = 0;
    uint64_t updates_ = 0;
    std::optional<PendingCapture> pending_capture_;
    std::filesystem::path capture_path_;
    std::string capture_error_;
    std::vector<std::filesystem::path> captures_;
    CaptureCompare compare_;
    mutable PanelState panel_state_;
    Workspace workspace_;  // registers its imgui.ini entry with the current ImGui context
    // Scene frames (inspector_frames.cpp).
    std::optional<FrameJob> last_posted_;
    bool dirty_ = true;           // render again whatever the job says (scene, shaders, capture)
    bool posted_moving_ = false;  // the last frame posted was posted while the camera moved
    bool view_dirty_ = false;     // a new frame to decode
    std::string decoded_key_;     // the view state the current decode used
    uint64_t view_version_ = 0;   // counts decodes: the presenter uploads a new version only
    VkExtent2D shown_nominal_{};  // the full render size of the frame shown (motion: larger)
    std::chrono::steady_clock::time_point last_motion_{};
    uint64_t frames_posted_ = 0;
    uint64_t frames_drawn_ = 0;  // frames_rendered_ when the panels drew it a second time
    uint64_t frames_seen_ = 0;   // frames_rendered_ when the panels last drew
    std::unique_ptr<RenderWorker> worker_;  // last: its thread stops before the rest goes
};

}  // namespace ds::ui
