#pragma once
// Scene frames off the UI thread. The inspector posts a FrameJob (camera, settings, size, what
// to read back); a render thread renders it and keeps the result until the UI takes it. One
// job waits at most: a newer post replaces a job not yet started (a change supersedes it),
// and the frame in flight, which cannot be stopped on the device, finishes and is shown as the
// newest finished frame.
//
// The Renderer belongs to the render thread while a frame is in flight. Anything else that
// uses it (loading a scene, reloading shaders, the advisor, pixel history, F12 captures) runs
// through exclusive(), which waits for the frame in flight. Renderer::describe_surface() is
// read from the UI thread without the lock: only set_scene() changes what it reads, and that
// runs inside exclusive().
//
// Synchronous mode (no thread) renders inside post(): `capture --ui`, `bench --ui` and tests
// that step the UI frame by frame see a new frame after every post.
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "renderer/renderer.h"

namespace ds::ui {

struct FrameJob {
    scene::Camera camera;
    Settings settings;
    VkExtent2D size{};        // rendered
    VkExtent2D nominal{};     // the full size it stands for (size is smaller while moving)
    bool camera_cut = false;  // the temporal passes start over (Renderer::camera_cut)
    ReadBack read_back = ReadBack::No;
    std::vector<InspectRequest> inspect;
    std::optional<SampleQuery> samples;  // the sample view's rectangle (zoomed in)
    uint64_t id = 0;                     // set by post()
};

struct FinishedFrame {
    FrameJob job;
    std::optional<FrameResult> frame;  // none: `error` says why
    std::string error;
    double ms = 0;  // wall time of the render, host side
};

class RenderWorker {
  public:
    RenderWorker(Renderer& renderer, bool threaded);
    ~RenderWorker();  // finishes the frame in flight, drops a waiting job, joins
    RenderWorker(const RenderWorker&) = delete;
    RenderWorker& operator=(const RenderWorker&) = delete;

    bool threaded() const { return thread_.joinable(); }
    // Queues `job` (replacing a job that has not started) and returns its id.
    uint64_t post(FrameJob job);
    // The newest finished frame not taken yet; frames finished before it are dropped.
    std::optional<FinishedFrame> take();
    // A job waits or renders.
    bool busy() const;
    // A finished frame waits to be taken.
    bool has_finished() const;
    // How long the frame in flight has rendered so far (0 when none).
    double in_flight_ms() const;
    // Runs `fn` with the renderer to itself: waits for the frame in flight first.
    void exclusive(const std::function<void(Renderer&)>& fn);
    // Called on the render thread after each frame (the window wakes its event loop with it).
    void on_finished(std::function<void()> fn);
    // Test hook: the render thread sleeps this long inside each frame (a slow scene frame).
    void set_frame_delay(std::chrono::milliseconds delay);

  private:
    void loop();
    FinishedFrame render(const FrameJob& job);

    Renderer& renderer_;
    std::mutex renderer_mutex_;  // held while a frame renders, and by exclusive()
    mutable std::mutex mutex_;   // everything below
    std::condition_variable wake_;
    std::optional<FrameJob> waiting_;
    std::optional<FinishedFrame> finished_;
    bool rendering_ = false, stop_ = false;
    std::chrono::steady_clock::time_point started_;
    uint64_t next_id_ = 1;
    std::chrono::milliseconds delay_{0};
    std::function<void()> on_finished_;
    std::thread thread_;  // last: started once everything above exists
};

}  // namespace ds::ui
