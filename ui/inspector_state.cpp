// What the inspector derives from a scene or a frame follows it (issue 24, "state follows the
// scene"): a pick is rendered again when the settings change and dropped when the scene or
// the render size changes; a selected Z-fight pair is found again by its surfaces in each new
// frame; a new scene drops every pick, selection, advice and compare pin of the old one.
#include "renderer/passes/zfight.h"
#include "ui/inspector.h"

namespace ds::ui {

void Inspector::render_pick(const Pick& pick) {
    try {
        FrameResult f;
        worker_->exclusive([&](Renderer& r) {
            f = r.render(camera_.camera(), settings_,
                         {.width = pick.size.width,
                          .height = pick.size.height,
                          .read_back = ReadBack::No,
                          .inspect = {},
                          .pixel = PixelQuery{pick.x, pick.y},
                          .samples = SampleQuery{pick.x, pick.y, 1, 1}});
        });
        pixel_history_ = f.copy_of<PixelHistory>();
        pixel_depth_ = f.depth;
        pixel_samples_ = f.copy_of<MsaaSamples>();
        pixel_label_ = scene_.name + " at " + std::to_string(pick.size.width) + "x" +
                       std::to_string(pick.size.height);
        pixel_error_.clear();
        pick_ = pick;
    } catch (const std::exception& e) {
        pixel_error_ = e.what();  // a pixel outside the frame, a refused setting
    }
}

void Inspector::repick() {
    if (pick_ && pixel_history_) render_pick(*pick_);
}

void Inspector::drop_pick() {
    pick_.reset();
    pixel_history_.reset();
    pixel_depth_.reset();
    pixel_samples_.reset();
    pixel_label_.clear();
    pixel_error_.clear();
}

void Inspector::drop_pick_of_other_size() {
    if (!pick_) return;
    const VkExtent2D size = render_size();
    if (size.width != pick_->size.width || size.height != pick_->size.height) drop_pick();
}

void Inspector::forget_scene_state() {
    drop_pick();
    viewer_.draw = -1;
    viewer_.zfight_pair = -1;
    advice_.reset();
    advice_label_.clear();
    advice_error_.clear();
    if (diagnosis_future_.valid()) {  // of the old scene: done by now (set_scene waited)
        try {
            diagnosis_future_.get();
        } catch (const std::exception&) {
        }
    }
    diagnosis_.reset();
    diagnosed_view_.reset();
    diagnosis_error_.clear();
    viewer_.finding = -1;
    finding_pair_.clear();
    compare_.unpin();  // a capture of another scene compares nothing
}

void Inspector::follow_selected_pair(const FrameResult& previous) {
    const int pair = viewer_.zfight_pair;
    if (pair < 0) return;
    viewer_.zfight_pair = -1;
    const ZfightResult* before = previous.find<ZfightResult>();
    const ZfightResult* now = frame_.find<ZfightResult>();
    if (!before || !now || size_t(pair) >= before->pairs.size()) return;
    const ZfightPair& selected = before->pairs[size_t(pair)];
    for (size_t i = 0; i < now->pairs.size(); ++i)
        if (now->pairs[i].a == selected.a && now->pairs[i].b == selected.b)
            viewer_.zfight_pair = int(i);
}

}  // namespace ds::ui
