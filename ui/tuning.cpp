#include "ui/tuning.h"

namespace ds::ui {

void Tuning::wait() {
    if (future_.valid()) future_.wait();
}

void Tuning::start(TuneKind kind, std::function<TuneResult()> work) {
    if (running()) return;
    kind_ = kind;
    error_.clear();
    started_ = std::chrono::steady_clock::now();
    future_ = std::async(std::launch::async, std::move(work));
}

bool Tuning::collect() {
    if (!running() || future_.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
        return false;
    try {
        TuneResult r = future_.get();
        if (r.msaa) msaa_ = std::move(r.msaa);
        if (r.alpha) alpha_ = std::move(r.alpha);
    } catch (const std::exception& e) {
        error_ = e.what();  // a scene without MASK materials, the prepass off ...
        future_ = {};
    }
    return true;
}

double Tuning::seconds() const {
    if (!running()) return 0.0;
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
}

}  // namespace ds::ui
