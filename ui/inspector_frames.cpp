// The inspector's scene frames: which frame the viewer needs next, whether it differs from the
// last one posted, taking finished frames from the render worker and decoding what is shown.
//
// Threaded (the window): a frame is posted only when the job changed (camera, settings, size,
// what is read back), something forced one (scene, shaders, a capture), or `continuous` is on.
// Temporal AO converges without extra frames: a job posted while the camera is at rest starts
// the temporal history over (a camera cut), and with the camera still the temporal pass's
// fixed point is its current input, so that first frame is the converged one
// (ui_inspector_tests compares it with a frame after many). While the camera moves, frames
// render at motion_scale and keep their history (reprojection smooths the motion); the frame
// after the camera stops is full size, from a cut.
#include <algorithm>
#include <cmath>
#include <utility>

#include <imgui.h>

#include "ui/inspector.h"

#include "ui/inspector_knobs.h"

namespace ds::ui {
namespace {

bool same_requests(const std::vector<InspectRequest>& a, const std::vector<InspectRequest>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                      [](const InspectRequest& x, const InspectRequest& y) {
                          return x.resource == y.resource && x.sample == y.sample;
                      });
}

bool same_rect(const std::optional<SampleQuery>& a, const std::optional<SampleQuery>& b) {
    if (!a || !b) return a.has_value() == b.has_value();
    return a->x == b->x && a->y == b->y && a->width == b->width && a->height == b->height;
}

// Whether two jobs render the same frame (ids and cuts aside).
bool same_frame(const FrameJob& a, const FrameJob& b) {
    return a.camera == b.camera && a.settings.diff(b.settings).empty() &&
           a.size.width == b.size.width && a.size.height == b.size.height &&
           a.read_back == b.read_back && same_requests(a.inspect, b.inspect) &&
           same_rect(a.samples, b.samples);
}

// Everything of the viewer's state that the decoded view depends on, as text: when it changes,
// the frame shown is decoded again (no new scene frame needed).
std::string view_key(const ViewerState& v, const CaptureCompare& compare) {
    std::string key = v.resource + '|' + std::to_string(v.sample) + '|' +
                      std::to_string(int(v.params.depth)) + std::to_string(v.params.auto_fit) +
                      '|' + std::to_string(v.params.black) + '|' + std::to_string(v.params.white) +
                      '|' + std::to_string(v.params.channel) + '|' +
                      std::to_string(v.params.exposure) + '|' + std::to_string(v.zfight_pair) +
                      '|' + std::to_string(v.draw) + '|' + std::to_string(v.finding) + '|' +
                      std::to_string(v.shared_count_scale);
    for (const Overlay& o : v.overlays)
        key += '|' + o.resource + ':' + std::to_string(o.opacity) + std::to_string(o.visible);
    key += '|' + std::to_string(int(v.compare.mode)) + ':' + std::to_string(v.compare.divider) +
           std::to_string(v.compare.match_size);
    if (compare.pinned()) key += '|' + compare.pinned()->dir.string();
    return key;
}

}  // namespace

bool Inspector::moving() const {
    return std::chrono::steady_clock::now() - last_motion_ < kMotionHold;
}

bool Inspector::idle() const {
    // A frame collected after the panels drew (update() runs after draw()) still needs one UI
    // frame: its timings, resources and labels would otherwise wait for the next input. The
    // last frame posted while the camera moved (motion_scale, smaller) is replaced by the
    // full-size one that the next update() posts, once the camera has been still kMotionHold.
    return !worker_->busy() && !worker_->has_finished() && !moving() && !posted_moving_ &&
           !pending_capture_ && !dirty_ && !knob_value(settings_, kContinuous) &&
           pending_.empty() && frames_drawn_ == frames_rendered_ && !diagnosing() &&
           !tuning_.running();
}

FrameJob Inspector::next_job() const {
    FrameJob job;
    job.camera = camera_.camera();
    job.settings = settings_;
    job.nominal = render_size();
    job.size = job.nominal;
    // A smaller frame while the camera moves; not for a fixed size (bench --ui) or the compare
    // view (it needs the pinned capture's size).
    const bool scalable = !options_.render_size && !compare_.active(viewer_.compare);
    if (worker_->threaded() && scalable && moving()) {
        const float s = knob_value(settings_, kMotionScale);
        job.size = {std::max(1u, uint32_t(std::lround(float(job.nominal.width) * s))),
                    std::max(1u, uint32_t(std::lround(float(job.nominal.height) * s)))};
    }
    // The shown image, the overlays and what they derive from, by the last frame's names. The
    // Z-fight heat map is drawn over the dimmed final image, the compare view compares it:
    // those read the colour back too.
    job.inspect = ViewComposer::request(viewer_, frame_.resources);
    job.read_back = viewer_.resource == kZfightImage || compare_.active(viewer_.compare)
                        ? ReadBack::Color
                        : ReadBack::No;
    // Zoomed in: every sample of the texels in view (full-size frames only: the rectangle is
    // in the full size's texels).
    const bool full_size =
        job.size.width == job.nominal.width && job.size.height == job.nominal.height;
    if (sample_view_wanted() && full_size && !compare_.active(viewer_.compare))
        job.samples = visible_sample_rect(viewer_.centre.x, viewer_.centre.y, viewer_.zoom,
                                          viewer_.w, viewer_.h, job.size.width, job.size.height);
    return job;
}

void Inspector::schedule() {
    FrameJob job = next_job();
    const bool now_moving = moving();
    // The camera stopped since the last frame was posted: that one kept the moving frames'
    // history (and may be smaller); the frame at rest starts it over.
    const bool stopped = posted_moving_ && !now_moving;
    const bool changed = dirty_ || stopped || !last_posted_ || !same_frame(job, *last_posted_);
    if (worker_->threaded()) {
        const bool again = knob_value(settings_, kContinuous) && !worker_->busy();
        if (!changed && !again) return;
        job.camera_cut = changed && !now_moving;
    }
    posted_moving_ = now_moving;
    last_posted_ = job;
    dirty_ = false;
    ++frames_posted_;
    worker_->post(std::move(job));
}

bool Inspector::collect() {
    std::optional<FinishedFrame> done = worker_->take();
    if (!done) return false;
    if (!done->frame) {
        // A setting the device refuses (msaa=8 on lavapipe ...): say so, go back to what worked.
        message_ = done->error;
        if (done->job.settings.diff(last_good_).empty()) {
            message_ += "; and the last good settings failed too";  // keep the previous frame
        } else if (done->job.settings.diff(settings_).empty()) {
            settings_ = last_good_;
            dirty_ = true;
        }
        return false;
    }
    const FrameResult previous = std::exchange(frame_, std::move(*done->frame));
    follow_selected_pair(previous);
    select_finding_pair();
    last_good_ = done->job.settings;
    shown_nominal_ = done->job.nominal;
    ++frames_rendered_;
    history_.add(frame_);
    view_dirty_ = true;
    return true;
}

void Inspector::refresh_view() {
    std::string key = view_key(viewer_, compare_);
    if (!view_dirty_ && key == decoded_key_) return;
    view_dirty_ = false;
    decoded_key_ = std::move(key);
    if (!frame_.width) return;
    ++view_version_;
    shown_ = composer_.decode_shown(frame_, viewer_, view_);
    if (shown_ && shown_->name == kZfightImage)
        view::overlay_counts(view_, *shown_, frame_.rgba8, 0.3f, selected_pair_pixels());
    composer_.stack_overlays(frame_, viewer_, view_);
    if (shown_) {  // over every overlay
        view::highlight(view_, selected_draw_pixels(), 0.25f);
        view::highlight(view_, selected_finding_pixels(), 0.25f);
    }
    compare_.compose(frame_, viewer_.compare);
}

}  // namespace ds::ui
