// The inspector's Diagnose (issue 24 point 5): capture/diagnose/diagnose_run.h's diagnosis of the
// current view, run off the UI thread (the UI goes on drawing; scene frames wait for the
// renderer meanwhile), its findings listed by the Diagnose panel. Selecting a finding
// highlights its pixels while the view is the one diagnosed, turns on the measurement its
// detector's panel shows (never a knob that changes the image) and opens that panel.
#include <algorithm>

#include "capture/diagnose/diagnose_run.h"
#include "renderer/passes/depth_precision.h"
#include "renderer/passes/draw_counts.h"
#include "renderer/passes/equal_check.h"
#include "renderer/passes/zfight.h"
#include "ui/inspector.h"

namespace ds::ui {
namespace {

// Where a detector's details are, and the measurement knob that panel needs ("" none).
struct DetailsPanel {
    const char* tab;
    const char* knob;
};

DetailsPanel details_of(const std::string& detector) {
    if (detector == "zfight" || detector == "decals")
        return {"Depth", passes::ZfightPass::kKnob.name};
    if (detector == "equal_check") return {"Depth", passes::EqualCheckPass::kKnob.name};
    if (detector == "depth_precision") return {"Depth", passes::DepthPrecisionPass::kKnob.name};
    if (detector == "draws") return {"Draws", passes::DrawCountsPass::kKnob.name};
    if (detector == "early_z") return {"Passes", ""};
    if (detector == "advisor") return {"Advisor", ""};
    return {"", ""};
}

}  // namespace

Inspector::~Inspector() {
    if (diagnosis_future_.valid()) diagnosis_future_.wait();
    tuning_.wait();
}

double Inspector::diagnosing_seconds() const {
    if (!diagnosing()) return 0.0;
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - diagnosis_started_)
        .count();
}

void Inspector::start_diagnosis() {
    if (diagnosing()) return;
    diagnosing_view_ = {camera_.camera(), settings_, render_size()};
    diagnosis_started_ = std::chrono::steady_clock::now();
    ++diagnoses_started_;
    diagnosis_error_.clear();
    // Its own copies: the UI thread may change the scene, settings and camera meanwhile (a new
    // scene waits in exclusive() until the diagnosis is done, then drops it).
    diagnosis_future_ =
        std::async(std::launch::async, [this, view = diagnosing_view_, scene = scene_]() {
            diagnose::Diagnosis d;
            worker_->exclusive([&](Renderer& r) {
                d = diagnose::diagnose(r, scene, view.camera, view.settings, view.size);
            });
            return d;
        });
}

void Inspector::collect_diagnosis() {
    if (!diagnosing() ||
        diagnosis_future_.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
        return;
    try {
        diagnosis_ = diagnosis_future_.get();
        diagnosed_view_ = diagnosing_view_;
    } catch (const std::exception& e) {
        diagnosis_error_ = e.what();  // a setting the device refuses ...
        diagnosis_future_ = {};
    }
    viewer_.finding = -1;
    dirty_ = true;  // the diagnosis's frames left the temporal passes' history behind
}

bool Inspector::diagnosis_current() const {
    if (!diagnosis_ || !diagnosed_view_) return false;
    const VkExtent2D size = render_size();
    if (size.width != diagnosed_view_->size.width || size.height != diagnosed_view_->size.height ||
        camera_.camera() != diagnosed_view_->camera)
        return false;
    // The measurement knobs ("zfight=on") a finding's panel turns on change no pixel.
    const std::vector<std::string>& measuring = diagnosis_->measurement_knobs;
    for (const std::string& name : settings_.diff(diagnosed_view_->settings))
        if (std::none_of(measuring.begin(), measuring.end(), [&](const std::string& m) {
                return m.compare(0, m.find('='), name) == 0;
            }))
            return false;
    return true;
}

std::vector<uint8_t> Inspector::selected_finding_pixels() const {
    std::vector<uint8_t> keep;
    const int index = viewer_.finding;
    if (index < 0 || !diagnosis_ || size_t(index) >= diagnosis_->findings.size() ||
        !diagnosis_current() || frame_.width != diagnosis_->width ||
        frame_.height != diagnosis_->height)
        return keep;
    const diagnose::Finding& f = diagnosis_->findings[size_t(index)];
    if (f.pixels.empty()) return keep;
    keep.assign(size_t(frame_.width) * frame_.height, 0);
    for (uint32_t p : f.pixels)
        if (p < keep.size()) keep[p] = 1;
    return keep;
}

void Inspector::select_finding(int index) {
    if (!diagnosis_ || index < 0 || size_t(index) >= diagnosis_->findings.size()) {
        viewer_.finding = -1;
        return;
    }
    viewer_.finding = index;
    const diagnose::Finding& finding = diagnosis_->findings[size_t(index)];
    const DetailsPanel panel = details_of(finding.detector);
    finding_pair_.clear();
    if (finding.surfaces.size() == 2 &&
        (finding.detector == "zfight" || finding.detector == "decals"))
        finding_pair_ = finding.surfaces;
    if (*panel.knob && settings_.get(panel.knob) != "on") {
        Settings changed = settings_;
        changed.set(panel.knob, "on");
        try {
            change_settings(changed);
        } catch (const std::exception& e) {
            message_ = e.what();
        }
    }
    if (*panel.tab) workspace_.select(panel.tab);
    select_finding_pair();
}

void Inspector::select_finding_pair() {
    const ZfightResult* z = frame_.find<ZfightResult>();
    if (finding_pair_.size() != 2 || !z) return;
    const auto same = [](const SurfaceName& s, const diagnose::FindingSurface& f) {
        return s.mesh == f.mesh && s.material == f.material && s.node == f.node;
    };
    const diagnose::FindingSurface &a = finding_pair_[0], &b = finding_pair_[1];
    for (size_t i = 0; i < z->pairs.size(); ++i) {
        const ZfightPair& p = z->pairs[i];
        if ((same(p.a, a) && same(p.b, b)) || (same(p.a, b) && same(p.b, a))) {
            viewer_.zfight_pair = int(i);
            finding_pair_.clear();
            return;
        }
    }
}

}  // namespace ds::ui
