#pragma once
// The compare view: the live frame's final image against a pinned capture's final.png, in the
// viewer. Split: the live frame left of a divider, the capture right of it. Diff: a heat map of
// the pixels where a channel differs by >= 8/255 (depthscope diff's rule, capture::diff_final,
// and its ramp, view::heat_color: black where nothing differs), with the % of such pixels.
// Images of two sizes are not compared: status() says so. Vulkan-free.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "capture/capture_folder.h"
#include "renderer/passes/frame_result.h"

namespace ds::ui {

enum class CompareMode : uint8_t { Off, Split, Diff };

// What the Compare panel sets (view state).
struct CompareState {
    CompareMode mode = CompareMode::Off;
    float divider = 0.5f;     // split: where the capture begins, 0..1 of the width
    bool match_size = false;  // render the live frame at the pinned capture's size
};

// A capture folder the live frame is compared against: its final.png, decoded.
struct PinnedCapture {
    std::filesystem::path dir;
    capture::Rgba8Image final_image;
};
// Reads DIR/final.png; throws ds::Error "PATH: …".
PinnedCapture read_pinned_capture(const std::filesystem::path& dir);

class CaptureCompare {
  public:
    static constexpr int kThreshold = 8;  // of 255, as `depthscope diff` by default

    void pin(PinnedCapture capture);
    void unpin();
    const std::optional<PinnedCapture>& pinned() const { return pinned_; }
    // A capture is pinned and a mode chosen: the frame must read its final image back.
    bool active(const CompareState& state) const {
        return pinned_ && state.mode != CompareMode::Off;
    }

    // After a frame (its final image read back): compares it with the pinned capture and
    // composes what `state` asks for; or empties the image and says why in status().
    void compose(const FrameResult& frame, const CompareState& state);

    // The composed image (RGBA8, top row first); empty when nothing is shown.
    const std::vector<uint8_t>& rgba8() const { return rgba8_; }
    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }
    // Why nothing is composed ("sizes differ: live 960x540, capture 1280x720"); "" when it is.
    const std::string& status() const { return status_; }
    // The last comparison: pixels over the threshold and their share; none when not compared.
    std::optional<uint64_t> differing() const { return differing_; }
    double percent() const { return percent_; }

  private:
    void split(const std::vector<uint8_t>& live, float divider);
    void heat(const std::vector<float>& heat);

    std::optional<PinnedCapture> pinned_;
    std::vector<uint8_t> rgba8_;
    uint32_t width_ = 0, height_ = 0;
    std::string status_;
    std::optional<uint64_t> differing_;
    double percent_ = 0;
};

}  // namespace ds::ui
