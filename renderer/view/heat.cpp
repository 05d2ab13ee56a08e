#include "renderer/view/heat.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "renderer/view/decode.h"
#include "renderer/view/pixel.h"

namespace ds::view {
namespace {

using detail::heat_index;
using detail::kHeatLutSize;
using detail::Range;
using detail::Rgb;

// The heat map's stops, t = 0+ .. 1 (t <= 0 is black).
constexpr std::array<Rgb, 6> kHeatStops{{
    {0, 40, 255},     // blue
    {0, 220, 255},    // cyan
    {0, 210, 40},     // green
    {255, 230, 0},    // yellow
    {235, 20, 0},     // red
    {255, 255, 255},  // white
}};

Rgb heat_exact(float t) {
    if (!(t > 0.0f)) return {0, 0, 0};
    t = std::min(t, 1.0f);
    float x = t * float(kHeatStops.size() - 1);
    size_t i = std::min(size_t(x), kHeatStops.size() - 2);
    float f = x - float(i);
    Rgb out{};
    for (size_t c = 0; c < 3; ++c) {
        float a = kHeatStops[i][c], b = kHeatStops[i + 1][c];
        out[c] = uint8_t(a + (b - a) * f + 0.5f);
    }
    return out;
}

struct HeatLut {
    std::array<Rgb, kHeatLutSize> table{};
    HeatLut() {
        table[0] = {0, 0, 0};
        for (int i = 1; i < kHeatLutSize; ++i) {
            // A tiny positive t for the first entry: the palette's first stop, not black.
            float t = std::max(float(i - 1) / 255.0f, std::numeric_limits<float>::min());
            table[size_t(i)] = heat_exact(t);
        }
    }
};

}  // namespace

const Rgb* detail::heat_table() {
    static const HeatLut lut;
    return lut.table.data();
}

std::array<uint8_t, 3> heat_color(float t) {
    if (std::isnan(t)) return {0, 0, 0};
    return detail::heat_table()[heat_index(t)];
}

std::array<uint8_t, 3> count_color(float count, float black, float white) {
    if (!std::isfinite(count)) return kNonFiniteColor;
    return detail::heat_table()[heat_index(Range::manual(black, white).t(count))];
}

std::vector<LegendStop> count_legend(float black, float white) {
    std::vector<LegendStop> stops;
    stops.push_back({black, {0, 0, 0}});
    if (!(white > black)) return stops;
    const float span = white - black;
    const bool whole = black == std::floor(black) && white == std::floor(white);
    if (whole && span <= 8.0f) {
        for (float c = black + 1.0f; c <= white; c += 1.0f) {
            stops.push_back({c, count_color(c, black, white)});
        }
        return stops;
    }
    // The first colour above black, then five evenly spaced counts up to white (whole counts
    // when the range is whole).
    stops.push_back({whole ? black + 1.0f : black + span / 255.0f, {}});
    for (int i = 1; i <= 5; ++i) {
        float c = black + span * float(i) / 5.0f;
        stops.push_back({whole ? std::round(c) : c, {}});
    }
    for (size_t i = 1; i < stops.size(); ++i) {
        stops[i].rgb = count_color(stops[i].count, black, white);
    }
    return stops;
}

std::vector<LegendStop> log_legend(float black, float white, int stops) {
    std::vector<LegendStop> out;
    if (!(black > 0.0f) || !(white > black) || stops < 2) return out;
    const float lo = std::log10(black), hi = std::log10(white);
    const Rgb* heat = detail::heat_table();
    for (int k = 0; k < stops; ++k) {
        const float t = float(k) / float(stops - 1);
        out.push_back(
            {std::pow(10.0f, lo + t * (hi - lo)), heat[std::max<size_t>(1, heat_index(t))]});
    }
    return out;
}

std::vector<LegendStop> display_legend(const graph::Display& display, float black, float white,
                                       int stops) {
    std::vector<LegendStop> out;
    if (black == white) {
        const Range flat = Range::flat(detail::scalar_shown(display.scale, black));
        out.push_back({black, detail::scalar_rgb(display, flat, black)});
        return out;
    }
    if (!(white > black) || stops < 2) return out;
    const Range r = detail::scalar_range(display.scale, black, white);
    const bool log = display.scale == graph::ValueScale::Log;
    for (int k = 0; k < stops; ++k) {
        const float shown = r.black + (r.white - r.black) * float(k) / float(stops - 1);
        const float value = log ? std::pow(10.0f, shown) : shown;
        out.push_back({value, detail::scalar_rgb(display, r, value)});
    }
    return out;
}

}  // namespace ds::view
