#include "ui/inspector.h"

#include "ui/inspector_knobs.h"

#include <algorithm>
#include <cmath>
#include <exception>

#include <imgui.h>

#include "renderer/passes/zfight.h"
#include "renderer/scene/loader.h"
#include "renderer/settings/frame_knobs.h"
#include "renderer/shader/compiler.h"
#include "ui/panels/panels.h"

namespace ds::ui {
namespace {

template <class... Ts>
struct Overloaded : Ts... {
    using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

SceneSummary summarize(const scene::Scene& s) {
    SceneSummary out;
    out.name = s.name;
    out.source = s.source;
    out.draw_groups = s.draw_groups.size();
    out.instances = s.instances.size();
    out.meshes = s.meshes.size();
    out.triangles = s.triangle_count();
    for (const scene::Material& m : s.materials) {
        switch (m.alpha_mode) {
            case scene::AlphaMode::Opaque:
                ++out.opaque;
                break;
            case scene::AlphaMode::Mask:
                ++out.masked;
                out.masked_materials.push_back({m.name, m.alpha_cutoff});
                break;
            case scene::AlphaMode::Blend:
                ++out.blend;
                break;
        }
    }
    return out;
}

}  // namespace

void PassHistory::add(const FrameResult& frame) {
    auto push = [](std::deque<double>& d, double v) {
        d.push_back(v);
        while (d.size() > kHistory) d.pop_front();
    };
    push(frame_ms, frame.gpu_ms);
    for (const PassResult& p : frame.passes) push(pass_ms[p.name], p.gpu_ms);
}

double PassHistory::median(const std::string& pass) const {
    const auto it = pass_ms.find(pass);
    if (it == pass_ms.end() || it->second.empty()) return 0.0;
    std::vector<double> v(it->second.begin(), it->second.end());
    const size_t mid = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + long(mid), v.end());
    if (v.size() % 2) return v[mid];
    const double upper = v[mid];
    return 0.5 * (upper + *std::max_element(v.begin(), v.begin() + long(mid)));
}

Inspector::Inspector(Renderer& renderer, Settings settings, scene::Scene scene, Options options)
    : renderer_(renderer),
      device_(device_info(renderer)),
      settings_(std::move(settings)),
      last_good_(settings_),
      options_(options),
      auto_reload_(options.watch_shaders),
      watch_(shader::Compiler::default_shader_root()),
      worker_(std::make_unique<RenderWorker>(renderer, options.threaded)) {
    set_scene(std::move(scene));
}

void Inspector::set_scene(scene::Scene scene) {
    worker_->exclusive([&](Renderer& r) { r.set_scene(scene); });  // throws, changing nothing
    dirty_ = true;
    scene_ = std::move(scene);
    summary_ = summarize(scene_);
    camera_.reset(scene_.camera, scene::content_bounds(scene_));
    forget_scene_state();  // no index into the previous scene's tables survives
    // Per-material cutoffs name the previous scene's materials: keep those this one has.
    auto cutoffs = knob_value(settings_, knobs::kMaterialAlphaCutoff);
    std::erase_if(cutoffs, [&](const auto& entry) {
        return std::none_of(summary_.masked_materials.begin(), summary_.masked_materials.end(),
                            [&](const SceneSummary::Masked& m) { return m.name == entry.first; });
    });
    const std::string kept = format_map(cutoffs);
    if (kept != settings_.get(knobs::kMaterialAlphaCutoff.name)) {
        set_knob(settings_, knobs::kMaterialAlphaCutoff, kept);
        set_knob(last_good_, knobs::kMaterialAlphaCutoff, kept);
    }
}

VkExtent2D Inspector::render_size() const {
    if (viewer_.compare.match_size && compare_.pinned()) {
        const capture::Rgba8Image& shot = compare_.pinned()->final_image;
        return {shot.width, shot.height};
    }
    if (options_.render_size) return *options_.render_size;
    float w = viewer_.w, h = viewer_.h;
    if (w < 1 || h < 1) {
        w = float(options_.fallback_width);
        h = float(options_.fallback_height);
    }
    const float scale = knob_value(settings_, kRenderScale);
    return {std::max(1u, uint32_t(std::lround(w * scale))),
            std::max(1u, uint32_t(std::lround(h * scale)))};
}

void apply_style() {
    ImGui::StyleColorsDark();
    ImGuiStyle& s = ImGui::GetStyle();
    s.WindowRounding = 0.0f;
    s.FrameRounding = 2.0f;
    // Opaque panels and popups: text behind them never shows through. Child windows (the
    // workspace's regions and tabs, scrolling tables) take the panels' colour.
    for (ImGuiCol c :
         {ImGuiCol_WindowBg, ImGuiCol_ChildBg, ImGuiCol_PopupBg, ImGuiCol_TitleBgCollapsed})
        s.Colors[c].w = 1.0f;
    s.Colors[ImGuiCol_ChildBg] = s.Colors[ImGuiCol_WindowBg];
}

ImDrawData* Inspector::run_frame() {
    ImGui::NewFrame();
    draw();
    update();
    ImGui::Render();
    return ImGui::GetDrawData();
}

bool Inspector::poll_shader_watch() {
    if (!auto_reload_ || !watch_.changed()) return false;
    pending_.push_back(ReloadShaders{});
    return true;
}

void Inspector::key_pressed(int key) {
    if (key == kCaptureKey) pending_.push_back(CaptureFrame{});  // anywhere in the window
}

void Inspector::draw() {
    // The panels below show the newest frame collected. ImGui fits table columns to what the
    // previous UI frame drew, so a new frame counts as drawn at its second UI frame: the UI
    // does not sleep with its tables laid out for the frame before.
    if (frames_seen_ == frames_rendered_) frames_drawn_ = frames_rendered_;
    frames_seen_ = frames_rendered_;
    PanelIo panel{*this, viewer_, camera_input_, pending_};
    workspace_.draw(panel);  // every panel in its tab, the viewer last
}

void Inspector::apply(const Action& action) {
    std::visit(
        Overloaded{
            [&](const SetSetting& a) { set_setting(a.name, a.value); },
            [&](const SelectResource& a) {
                viewer_.resource = a.name;
                viewer_.sample = 0;
                viewer_.hover.reset();
            },
            [&](const SelectPass& a) { selected_pass_ = a.name; },
            [&](const LoadScene& a) { load_named_scene(a.name_or_path); },
            [&](const ReloadShaders&) { reload_shaders(); },
            [&](const SetAutoReload& a) { auto_reload_ = a.on; },
            [&](const ResetSettings&) { set_settings_or_say(Settings()); },
            [&](const MeasureAdvice&) { measure_advice(); },
            [&](const SceneCamera&) { camera_.reset(scene_.camera); },
            [&](const GoToCamera& a) { go_to_camera(a.index); },
            [&](const FitInside&) { fit_inside(); },
            [&](const AddBookmark& a) { add_bookmark(a.name); },
            [&](const GoToBookmark& a) {
                if (const auto* c = bookmarks_.find(bookmark_key(scene_), a.name))
                    camera_.reset(*c);
            },
            [&](const DeleteBookmark& a) { bookmarks_.remove(bookmark_key(scene_), a.name); },
            [&](const Diagnose&) { start_diagnosis(); },
            [&](const Tune& t) { start_tuning(t); },
            [&](const SelectFinding& a) { select_finding(a.index); },
            [&](const AddOverlay& a) { viewer_.overlays.push_back({a.resource}); },
            [&](const RemoveOverlay& a) {
                if (a.index < viewer_.overlays.size())
                    viewer_.overlays.erase(viewer_.overlays.begin() + long(a.index));
            },
            [&](const MoveOverlay& a) {
                const long to = long(a.index) + a.by;
                if (a.index < viewer_.overlays.size() && to >= 0 &&
                    size_t(to) < viewer_.overlays.size())
                    std::swap(viewer_.overlays[a.index], viewer_.overlays[size_t(to)]);
            },
            [&](const PickPixel& a) { pick_pixel(a); },
            [&](const CaptureFrame&) { request_capture(); },
            [&](const PinCapture& a) { pin_capture(a.dir); },
        },
        action);
}

void Inspector::set_setting(const std::string& name, const std::string& value) {
    Settings changed = settings_;
    try {
        changed.set(name, value);
    } catch (const std::exception& e) {
        message_ = e.what();  // nothing changed
        return;
    }
    set_settings_or_say(changed);
}

void Inspector::set_settings_or_say(const Settings& changed) {
    try {
        change_settings(changed);
    } catch (const std::exception& e) {
        message_ = e.what();  // nothing changed
    }
}

void Inspector::load_named_scene(const std::string& name_or_path) {
    try {
        scene::Scene loaded = scene::load_scene(name_or_path, settings_);
        set_scene(std::move(loaded));
        history_ = {};
        message_.clear();
    } catch (const std::exception& e) {
        message_ = e.what();  // the current scene stays
    }
}

void Inspector::reload_shaders() {
    dirty_ = true;
    try {
        worker_->exclusive([](Renderer& r) { r.rebuild_pipelines(); });
        shader_status_ = "shaders reloaded";
        shader_error_ = false;
    } catch (const std::exception& e) {
        shader_status_ = e.what();  // file:line; the last good pipelines keep running
        shader_error_ = true;
    }
}

void Inspector::change_settings(const Settings& changed) {
    // A built-in scene built from settings (overdraw_layers ...) is rebuilt first: if that
    // throws, nothing has changed.
    const bool builtin = scene_.source.rfind("builtin:", 0) == 0;
    bool rebuild = false;
    for (const std::string& name : changed.diff(settings_))
        rebuild =
            rebuild || SettingsRegistry::instance().at(name).invalidates == Invalidates::Scene;
    if (builtin && rebuild) {
        scene::Scene rebuilt = scene::load_scene(scene_.name, changed);
        settings_ = changed;
        set_scene(std::move(rebuilt));
    } else {
        settings_ = changed;
        repick();  // the picked pixel's history under the new settings
    }
    message_.clear();
}

void Inspector::update() {
    ++updates_;
    capture_when_shown();
    poll_shader_watch();
    std::vector<Action> actions;
    actions.swap(pending_);
    for (const Action& a : actions) apply(a);
    drop_pick_of_other_size();
    camera_input_.dt =
        std::clamp(ImGui::GetCurrentContext() ? ImGui::GetIO().DeltaTime : 0.016f, 0.0f, 0.25f);
    camera_input_.viewport_height = std::max(viewer_.h, 1.0f);
    if (camera_.update(camera_input_)) last_motion_ = std::chrono::steady_clock::now();
    camera_input_ = CameraInput{};
    collect_diagnosis();
    if (tuning_.collect()) dirty_ = true;  // its frames left the temporal history behind
    schedule();
    // A frame the device refused: settings went back to the last good ones; render those now
    // (synchronous mode: within this update, as the user expects).
    if (!collect() && !worker_->threaded() && dirty_) {
        schedule();
        collect();
    }
    refresh_view();
}

// Both configurations through the inspector's renderer, camera, size and settings; the next
// frame renders the settings as they are again.
void Inspector::measure_advice() {
    const VkExtent2D size = render_size();
    const scene::Camera camera = camera_.camera();
    try {  // the default run's frames block the UI meanwhile
        worker_->exclusive([&](Renderer& renderer) {
            const capture::RenderFrame render = [&](const Settings& s) {
                return renderer.render(
                    camera, s,
                    {.width = size.width, .height = size.height, .read_back = ReadBack::No});
            };
            advice_ =
                capture::advise(capture::measure_advice(settings_, render, capture::AdviceRun{}));
        });
        advice_label_ =
            scene_.name + " at " + std::to_string(size.width) + "x" + std::to_string(size.height);
        advice_error_.clear();
    } catch (const std::exception& e) {
        advice_error_ = e.what();  // the last advice, if any, stays
    }
}

// One frame more with the pixel history of `pick` (the frame the inspector shows is not
// replaced: a history frame adds replay passes to the pass list and timings).
void Inspector::pick_pixel(const PickPixel& pick) {
    const VkExtent2D size = render_size();
    ++pixel_picks_;
    // The pick names a texel of the frame shown, which may be a smaller one rendered while the
    // camera moved: the history is of the same point at the full size.
    const uint32_t x =
        frame_.width ? uint32_t(uint64_t(pick.x) * size.width / frame_.width) : pick.x;
    const uint32_t y =
        frame_.height ? uint32_t(uint64_t(pick.y) * size.height / frame_.height) : pick.y;
    render_pick({x, y, size});
}

// The selected zfight pair's pixels as a keep mask (empty: no pair selected, show all).
std::vector<uint8_t> Inspector::selected_pair_pixels() const {
    std::vector<uint8_t> keep;
    const int pair = viewer_.zfight_pair;
    const ZfightResult* zfight = frame_.find<ZfightResult>();
    if (pair < 0 || !zfight || size_t(pair) >= zfight->pairs.size()) return keep;
    keep.assign(size_t(frame_.width) * frame_.height, 0);
    for (const ZfightHit& h : zfight->hits)
        if (h.pair == uint32_t(pair) && h.pixel < keep.size()) keep[h.pixel] = 1;
    return keep;
}

std::vector<uint8_t> Inspector::selected_draw_pixels() const {
    std::vector<uint8_t> keep;
    const int draw = viewer_.draw;
    const DrawsResult* draws = frame_.find<DrawsResult>();
    if (draw < 0 || !draws || draws->draw_pixels.empty()) return keep;
    keep.resize(draws->draw_pixels.size());
    for (size_t i = 0; i < keep.size(); ++i) keep[i] = draws->draw_pixels[i] == uint32_t(draw) + 1;
    return keep;
}

// What fights at a zfight pixel, pair by pair: "coplanar_a_0 vs coplanar_b_0 (1 step, 12 um)",
// the gap in depth steps and in scene units along the view ray.
std::string Inspector::zfight_text(uint32_t x, uint32_t y) const {
    const ZfightResult* zfight = frame_.find<ZfightResult>();
    if (!zfight) return {};
    const uint32_t pixel = y * frame_.width + x;
    const auto& hits = zfight->hits;
    auto it = std::lower_bound(hits.begin(), hits.end(), pixel,
                               [](const ZfightHit& h, uint32_t p) { return h.pixel < p; });
    std::string out;
    for (; it != hits.end() && it->pixel == pixel; ++it) {
        const ZfightPair& p = zfight->pairs[it->pair];
        out += (out.empty() ? ": " : "; ") + p.a.node + " vs " + p.b.node + " (" +
               std::to_string(it->steps) + (it->steps == 1 ? " step, " : " steps, ") +
               view::length_text(it->gap) + ")";
    }
    return out;
}

std::optional<view::Readout> Inspector::readout_at(uint32_t x, uint32_t y) const {
    if (!shown_) return std::nullopt;
    std::optional<view::Readout> r = view::readout(*shown_, x, y);
    if (r && ViewComposer::derived(shown_->name))
        r->decoded_text = composer_.text_at(frame_, shown_->name, x, y);
    // A surface id names its surface: the view library knows ids, the renderer the scene.
    if (r && shown_->semantic == graph::Semantic::SurfaceId)
        if (const auto s = renderer_.describe_surface(uint32_t(r->raw[0])))
            r->decoded_text += ": mesh " + s->name.mesh + ", material " + s->name.material +
                               ", node " + s->name.node + ", triangle " +
                               std::to_string(s->triangle);
    if (r && shown_->name == kZfightImage) r->decoded_text += zfight_text(x, y);
    return r;
}

std::string Inspector::overlay_text(uint32_t x, uint32_t y) const {
    std::string out;
    const std::vector<std::string>& status = composer_.overlay_status();
    for (size_t i = 0; i < viewer_.overlays.size() && i < status.size(); ++i) {
        if (!status[i].empty()) continue;  // not drawn
        const std::string& name = viewer_.overlays[i].resource;
        out += (out.empty() ? "" : "  |  ") + name + ": " + composer_.text_at(frame_, name, x, y);
    }
    return out;
}

ViewerBlit Inspector::viewer_blit() const {
    ViewerBlit b;
    if (view_.rgba8.empty() || viewer_.w < 1 || viewer_.h < 1) return b;
    const bool compared = !compare_.rgba8().empty();  // the compare view replaces the image
    b.rgba8 = compared ? &compare_.rgba8() : &view_.rgba8;
    b.width = compared ? compare_.width() : view_.width;
    b.height = compared ? compare_.height() : view_.height;
    b.dst_x = viewer_.x;
    b.dst_y = viewer_.y;
    b.dst_w = viewer_.w;
    b.dst_h = viewer_.h;
    // zoom counts screen pixels per texel of the full-size frame; a frame rendered smaller
    // while the camera moved covers the same area.
    const float zoom = std::max(viewer_.zoom, 1e-3f);
    const float sx =
        shown_nominal_.width && !compared ? float(b.width) / float(shown_nominal_.width) : 1.0f;
    const float sy =
        shown_nominal_.height && !compared ? float(b.height) / float(shown_nominal_.height) : 1.0f;
    b.src_w = viewer_.w / zoom * sx;
    b.src_h = viewer_.h / zoom * sy;
    b.src_x = viewer_.centre.x * float(b.width) - 0.5f * b.src_w;
    b.src_y = viewer_.centre.y * float(b.height) - 0.5f * b.src_h;
    b.nearest = zoom >= sx;
    b.version = view_version_;
    return b;
}

const MsaaSamples* Inspector::shown_samples() const {
    if (!sample_view_wanted()) return nullptr;
    return frame_.find<MsaaSamples>();
}

std::optional<SurfaceInfo> Inspector::describe_surface(uint32_t id) const {
    return renderer_.describe_surface(id);
}

std::optional<PixelSampleList> Inspector::sample_list_at(uint32_t x, uint32_t y) const {
    const MsaaSamples* samples = shown_samples();
    if (!samples || !frame_.depth) return std::nullopt;
    return sample_list(*samples, x, y, *frame_.depth, device_.standard_sample_locations,
                       [this](uint32_t id) { return describe_surface(id); });
}

std::vector<CoverageRow> Inspector::pixel_coverage() const {
    if (!pixel_history_ || !pixel_samples_ || pixel_samples_->samples < 2) return {};
    return coverage_rows(*pixel_history_, *pixel_samples_,
                         [this](uint32_t id) { return describe_surface(id); });
}

}  // namespace ds::ui
