// The Tuning panel's runs: capture/tune/'s sweeps on the current view (camera, settings, render
// size), off the UI thread with the renderer held, as Diagnose runs (inspector_diagnose.cpp).
#include "ui/inspector.h"

namespace ds::ui {

void Inspector::start_tuning(const Tune& t) {
    const VkExtent2D size = render_size();
    tuning_.start(
        t.kind, [this, t, size, camera = camera_.camera(), settings = settings_, scene = scene_]() {
            TuneResult r;
            worker_->exclusive([&](Renderer& renderer) {
                if (t.kind == TuneKind::Msaa)
                    r.msaa = tune::tune_msaa(renderer, scene, camera, settings, size, t.cost);
                else {
                    tune::AlphaSweep sweep;
                    sweep.cost_kind = t.cost;
                    r.alpha = tune::tune_alpha(renderer, scene, camera, settings, size, sweep);
                }
            });
            return r;
        });
}

}  // namespace ds::ui
