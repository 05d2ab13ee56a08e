#include "ui/compare.h"

#include <algorithm>
#include <cmath>

#include "capture/capture_diff.h"
#include "renderer/view/heat.h"

namespace ds::ui {
namespace {

constexpr uint8_t kDividerRgb[3] = {255, 210, 0};  // the split's line: yellow, seen on any frame

std::string size_text(uint32_t w, uint32_t h) {
    return std::to_string(w) + "x" + std::to_string(h);
}

}  // namespace

PinnedCapture read_pinned_capture(const std::filesystem::path& dir) {
    return {dir, capture::read_png_rgba8(dir / "final.png")};
}

void CaptureCompare::pin(PinnedCapture capture) {
    pinned_ = std::move(capture);
    differing_.reset();
}

void CaptureCompare::unpin() {
    pinned_.reset();
    rgba8_.clear();
    status_.clear();
    differing_.reset();
}

void CaptureCompare::compose(const FrameResult& frame, const CompareState& state) {
    rgba8_.clear();
    width_ = height_ = 0;
    differing_.reset();
    status_.clear();
    if (!active(state)) return;
    const capture::Rgba8Image& shot = pinned_->final_image;
    if (frame.rgba8.empty()) {
        status_ = "the live frame has no final image";
        return;
    }
    if (frame.width != shot.width || frame.height != shot.height) {
        status_ = "sizes differ: live " + size_text(frame.width, frame.height) + ", capture " +
                  size_text(shot.width, shot.height) + " (render at the capture's size)";
        return;
    }
    const capture::Rgba8Image live{frame.width, frame.height, frame.rgba8};
    const capture::ImageDiff diff = capture::diff_final(live, shot, kThreshold);
    differing_ = diff.differing;
    percent_ = diff.percent();
    width_ = frame.width;
    height_ = frame.height;
    if (state.mode == CompareMode::Split)
        split(frame.rgba8, state.divider);
    else
        heat(diff.heat);
}

// Live pixels left of the divider's column, the capture's from it on, the column itself a line.
void CaptureCompare::split(const std::vector<uint8_t>& live, float divider) {
    const std::vector<uint8_t>& shot = pinned_->final_image.rgba;
    rgba8_ = live;
    const uint32_t column =
        std::min(width_ - 1, uint32_t(std::lround(std::clamp(divider, 0.0f, 1.0f) * width_)));
    for (uint32_t y = 0; y < height_; ++y) {
        const size_t row = size_t(y) * width_ * 4;
        std::copy(shot.begin() + long(row + size_t(column) * 4),
                  shot.begin() + long(row + width_ * 4),
                  rgba8_.begin() + long(row + size_t(column) * 4));
        uint8_t* line = &rgba8_[row + size_t(column) * 4];
        std::copy(kDividerRgb, kDividerRgb + 3, line);
        line[3] = 255;
    }
}

// depthscope diff's heat map: black where no channel differs by the threshold, else the heat
// ramp at the pixel's difference over the image's largest.
void CaptureCompare::heat(const std::vector<float>& heat) {
    rgba8_.assign(size_t(width_) * height_ * 4, 0);
    for (size_t p = 0; p < heat.size(); ++p) {
        const std::array<uint8_t, 3> c =
            heat[p] > 0.0f ? view::heat_color(heat[p]) : std::array<uint8_t, 3>{};
        std::copy(c.begin(), c.end(), rgba8_.begin() + long(p * 4));
        rgba8_[p * 4 + 3] = 255;
    }
}

}  // namespace ds::ui
