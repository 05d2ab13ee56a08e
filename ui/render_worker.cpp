#include "ui/render_worker.h"

#include <exception>

namespace ds::ui {

RenderWorker::RenderWorker(Renderer& renderer, bool threaded) : renderer_(renderer) {
    if (threaded) thread_ = std::thread([this] { loop(); });
}

RenderWorker::~RenderWorker() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
        waiting_.reset();
    }
    wake_.notify_all();
    if (thread_.joinable()) thread_.join();
}

uint64_t RenderWorker::post(FrameJob job) {
    std::unique_lock lock(mutex_);
    job.id = next_id_++;
    const uint64_t id = job.id;
    if (!threaded()) {
        lock.unlock();
        FinishedFrame done = render(job);
        lock.lock();
        finished_ = std::move(done);
        return id;
    }
    waiting_ = std::move(job);
    lock.unlock();
    wake_.notify_all();
    return id;
}

std::optional<FinishedFrame> RenderWorker::take() {
    std::lock_guard lock(mutex_);
    std::optional<FinishedFrame> out = std::move(finished_);
    finished_.reset();
    return out;
}

bool RenderWorker::busy() const {
    std::lock_guard lock(mutex_);
    return rendering_ || waiting_.has_value();
}

bool RenderWorker::has_finished() const {
    std::lock_guard lock(mutex_);
    return finished_.has_value();
}

double RenderWorker::in_flight_ms() const {
    std::lock_guard lock(mutex_);
    if (!rendering_) return 0.0;
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started_)
        .count();
}

void RenderWorker::exclusive(const std::function<void(Renderer&)>& fn) {
    std::lock_guard lock(renderer_mutex_);
    fn(renderer_);
}

void RenderWorker::on_finished(std::function<void()> fn) {
    std::lock_guard lock(mutex_);
    on_finished_ = std::move(fn);
}

void RenderWorker::set_frame_delay(std::chrono::milliseconds delay) {
    std::lock_guard lock(mutex_);
    delay_ = delay;
}

void RenderWorker::loop() {
    std::unique_lock lock(mutex_);
    for (;;) {
        wake_.wait(lock, [&] { return stop_ || waiting_.has_value(); });
        if (stop_) return;
        FrameJob job = std::move(*waiting_);
        waiting_.reset();
        rendering_ = true;
        started_ = std::chrono::steady_clock::now();
        lock.unlock();
        FinishedFrame done = render(job);
        lock.lock();
        rendering_ = false;
        finished_ = std::move(done);  // an older frame nobody took is dropped
        if (on_finished_) on_finished_();
    }
}

FinishedFrame RenderWorker::render(const FrameJob& job) {
    FinishedFrame out{job, std::nullopt, {}, 0};
    std::chrono::milliseconds delay;
    {
        std::lock_guard lock(mutex_);
        delay = delay_;
    }
    const auto start = std::chrono::steady_clock::now();
    {
        std::lock_guard renderer_lock(renderer_mutex_);
        if (delay.count() > 0) std::this_thread::sleep_for(delay);
        try {
            if (job.camera_cut) renderer_.camera_cut();
            out.frame = renderer_.render(job.camera, job.settings,
                                         {.width = job.size.width,
                                          .height = job.size.height,
                                          .read_back = job.read_back,
                                          .inspect = job.inspect,
                                          .pixel = std::nullopt,
                                          .samples = job.samples});
        } catch (const std::exception& e) {
            out.error = e.what();
        }
    }
    out.ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return out;
}

}  // namespace ds::ui
