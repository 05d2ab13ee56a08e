#pragma once
// The inspector's read-only mode for a layer capture (`depthscope view --capture DIR` on a
// folder `depthscope layer` wrote): no scene to render again, so everything comes from the
// folder's files. A left column holds the capture (application, device, frame, cost, what was
// not analysed), its passes and the selected pass's draws with their counts; the rest of the
// window shows the selected pass's count image (shaded, discarded or rasterized, and where the
// capture has them zfight competitors or the EQUAL check's marks) fitted, with the hovered
// pixel's values read out; the Z-fight pairs and the EQUAL check's totals are listed.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "capture/layer_capture_data.h"
#include "ui/viewer_blit.h"

namespace ds::ui {

class LayerViewer {
  public:
    explicit LayerViewer(capture::LayerCaptureData data);

    // The panels, inside an ImGui frame (NewFrame ... Render) of `target`'s size.
    void draw(TargetSize target);
    // The image and where it goes, for the presenter (valid until the next draw()).
    const ViewerBlit& blit() const { return blit_; }

    // An index into data().images, a kind of capture::kLayerImageKinds (0: one it lacks).
    void select(size_t pass_image, size_t kind);
    const capture::LayerCaptureData& data() const { return data_; }
    // The hovered pixel's readout ("x, y: shaded …"), empty when the cursor is not on the image.
    const std::string& readout() const { return readout_; }

  private:
    void draw_summary();
    void draw_passes();
    void draw_depth_checks();
    void draw_draws();
    void update_blit(TargetSize target);
    void update_readout(TargetSize target);

    capture::LayerCaptureData data_;
    size_t image_ = 0, kind_ = 0;
    std::vector<uint8_t> rgba_;
    uint64_t version_ = 0;
    ViewerBlit blit_;
    std::string readout_;
};

}  // namespace ds::ui
