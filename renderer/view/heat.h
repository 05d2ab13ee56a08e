#pragma once
// The count heat map of the view library: the colours a Count image decodes to (decode.h) and
// the legend that explains them, from the same table so the legend matches the pixels.
#include <array>
#include <cstdint>
#include <vector>

#include "renderer/graph/display.h"

namespace ds::view {

// The count heat map: t in 0..1 over black -> blue -> cyan -> green -> yellow -> red -> white;
// t <= 0 is black; quantised to the 256 steps decode uses. count_color maps a count over a
// black..white range exactly as decode does.
std::array<uint8_t, 3> heat_color(float t);
std::array<uint8_t, 3> count_color(float count, float black, float white);
struct LegendStop {
    float count = 0;  // the count (or value) this colour means
    std::array<uint8_t, 3> rgb{};
};
// Stops for a legend of a Count view's range (DecodedView::black/white): the first is black
// (counts <= black); then every count when the range is at most 8 whole counts, else the
// first colour above black and five evenly spaced counts ending at white (whole counts when
// black and white are).
std::vector<LegendStop> count_legend(float black, float white);
// Stops for a log-scale view (depth_precision: DecodedView::black/white in scene units, both
// > 0): `stops` values evenly spaced in log10 from black to white, with the colours decode
// gives them (the first colour above black at black).
std::vector<LegendStop> log_legend(float black, float white, int stops = 6);
// Stops for a Scalar image's colour bar (graph/display.h; DecodedView::black/white, in the
// value's unit): `stops` values evenly spaced over the shown quantity (log10 v for Log) from
// black to white, each in the colour decode gives it. A flat range (black == white) is one
// stop, in decode's mid colour; black > white, or stops < 2: none.
std::vector<LegendStop> display_legend(const graph::Display& display, float black, float white,
                                       int stops = 64);

}  // namespace ds::view
