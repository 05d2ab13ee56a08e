// The inspector's captures (F12, the Capture button) and the compare view's pinned capture.
#include <exception>

#include "capture/capture_writer.h"
#include "capture/output_dir.h"
#include "ui/inspector.h"

namespace ds::ui {

// The camera and size of the frame on the screen now; the capture itself waits until the
// next frame has shown "capturing…" (the UI waits for it: seconds at a large size on lavapipe).
void Inspector::request_capture() {
    if (!pending_capture_)
        pending_capture_ = PendingCapture{camera_.camera(), render_size(), updates_};
}

void Inspector::capture_when_shown() {
    // Asked in update k, "capturing…" drawn and presented in UI frame k + 1: now is k + 2.
    if (!pending_capture_ || updates_ < pending_capture_->update + 2) return;
    const PendingCapture request = *pending_capture_;
    pending_capture_.reset();
    capture_frame(request);
}

// A normal capture (final.png, every resource, report.json; `depthscope replay` renders it
// again bit for bit) of what the viewer showed: that camera and render size, these settings,
// through the live renderer (capture/capture_writer.h). The capture renders from a camera
// cut, so the inspector's temporal history stays out of it; the next live frame continues
// from the capture's own history (the same camera) and is the captured frame bit for bit
// (ui_capture_tests).
void Inspector::capture_frame(const PendingCapture& request) {
    const capture::ResourceSelection every_resource;  // capture's default: all
    try {
        capture::OutputDir out(capture::default_capture_dir(options_.capture_root, scene_.name));
        dirty_ = true;  // the capture's frame replaced the renderer's temporal history
        worker_->exclusive([&](Renderer& renderer) {
            write_frame_capture(renderer,
                                {scene_, request.camera, settings_, request.size.width,
                                 request.size.height, every_resource},
                                out);
        });
        const std::string warning = out.commit();
        capture_path_ = out.final_dir();
        captures_.push_back(capture_path_);
        capture_error_ = warning;  // in place, but old files were left behind
        pin_capture(capture_path_);
    } catch (const std::exception& e) {
        capture_error_ = e.what();  // the staging folder is gone; the last capture stays
    }
}

void Inspector::pin_capture(const std::filesystem::path& dir) {
    if (dir.empty()) {
        compare_.unpin();
        return;
    }
    try {
        compare_.pin(read_pinned_capture(dir));
        message_.clear();
    } catch (const std::exception& e) {
        message_ = e.what();  // the pinned capture, if any, stays
    }
}

}  // namespace ds::ui
