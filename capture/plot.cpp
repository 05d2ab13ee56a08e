#include "capture/plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "capture/file_output.h"
#include "capture/image_writer.h"
#include "capture/plot_raster.h"
#include "renderer/common/error.h"
#include "renderer/common/quoted.h"

namespace ds::capture {
namespace {

constexpr uint32_t kPlotMaxSide = 8192;
constexpr int kTextScale = 2;   // title, axis labels, tick labels, legend
constexpr int kSmallScale = 1;  // point labels
constexpr uint32_t kBackground = 0xffffff, kInk = 0x222222, kGrid = 0xe4e4e4;
constexpr uint32_t kPointLabel = 0x404040, kNoData = 0x909090;
constexpr double kMarkerRadius = 4.0;
constexpr int kLineThickness = 2, kTickLength = 5, kPad = 8, kInset = 8;

std::string format_number(const char* format, double v, int decimals = 0) {
    char text[64];
    std::snprintf(text, sizeof text, format, decimals, v);
    return text;
}

// The step of 1, 2 or 5 times a power of ten nearest to span / target.
double nice_step(double span, int target) {
    const double raw = span / std::max(target, 1);
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    const double n = raw / magnitude;
    return (n < 1.5 ? 1 : n < 3 ? 2 : n < 7 ? 5 : 10) * magnitude;
}

// Two ticks at the ends, for spans the steps cannot cover (overflowing or vanishing ones).
PlotAxis two_tick_axis(double lo, double hi) {
    PlotAxis a{lo, hi, {lo, hi}, {format_number("%.*g", lo, 4), format_number("%.*g", hi, 4)}};
    if (!(a.hi > a.lo)) a.hi = a.lo + 1;
    return a;
}

// The data's range per axis over every drawable point; nullopt when there is none.
struct DataRange {
    double x0, x1, y0, y1;
};

bool drawable(const std::pair<double, double>& p, bool log_x) {
    return std::isfinite(p.first) && std::isfinite(p.second) && (!log_x || p.first > 0);
}

std::optional<DataRange> data_range(const Plot& plot) {
    std::optional<DataRange> r;
    for (const PlotSeries& s : plot.series)
        for (const auto& p : s.points) {
            if (!drawable(p, plot.log_x)) continue;
            if (!r) r = DataRange{p.first, p.first, p.second, p.second};
            r->x0 = std::min(r->x0, p.first);
            r->x1 = std::max(r->x1, p.first);
            r->y0 = std::min(r->y0, p.second);
            r->y1 = std::max(r->y1, p.second);
        }
    return r;
}

struct LegendEntry {
    const PlotSeries* series;
    int x, y;  // the entry's top-left
};

constexpr int kLegendSample = 24;  // the line and marker before a label
constexpr int kLegendGap = 20;     // between entries

int legend_entry_width(const PlotSeries& s) {
    return kLegendSample + 6 + Canvas::text_width(s.label, kTextScale) + kLegendGap;
}

// The legend's entries in rows under the x label, wrapped to the image's width, each row
// centred.
std::vector<LegendEntry> legend_layout(const Plot& plot, int width, int top) {
    std::vector<LegendEntry> out;
    int x = kPad * 2, y = top;
    const int row = Canvas::text_height(kTextScale) + 6;
    for (const PlotSeries& s : plot.series) {
        if (s.label.empty()) continue;
        const int w = legend_entry_width(s);
        if (x > kPad * 2 && x + w > width - kPad) x = kPad * 2, y += row;
        out.push_back({&s, x, y});
        x += w;
    }
    for (size_t i = 0; i < out.size();) {
        size_t end = i;
        while (end < out.size() && out[end].y == out[i].y) ++end;
        const LegendEntry& last = out[end - 1];
        const int used = last.x + legend_entry_width(*last.series) - kLegendGap - out[i].x;
        const int shift = std::max(0, (width - used) / 2 - out[i].x);
        for (; i < end; ++i) out[i].x += shift;
    }
    return out;
}

int legend_rows(const Plot& plot, int width) {
    const std::vector<LegendEntry> entries = legend_layout(plot, width, 0);
    if (entries.empty()) return 0;
    return entries.back().y / (Canvas::text_height(kTextScale) + 6) + 1;
}

int widest(const std::vector<std::string>& texts) {
    int w = 0;
    for (const std::string& t : texts) w = std::max(w, Canvas::text_width(t, kTextScale));
    return w;
}

int round_px(double v) {
    return int(std::lround(v));
}

// Grid lines across the frame and tick marks outside it at the ticks, their labels beyond.
void draw_axes(Canvas& c, const PlotLayout& l) {
    const int line = Canvas::text_height(kTextScale);
    const int x0 = l.left - l.inset, x1 = l.right + l.inset;
    const int y0 = l.top - l.inset, y1 = l.bottom + l.inset;
    for (size_t i = 0; i < l.x.ticks.size(); ++i) {
        const int x = round_px(l.to_pixel(l.x.ticks[i], l.y.lo).first);
        c.fill_rect(x, y0, x + 1, y1, kGrid);
        c.fill_rect(x, y1, x + 1, y1 + kTickLength, kInk);
        const int w = Canvas::text_width(l.x.tick_labels[i], kTextScale);
        c.text(x - w / 2, y1 + kTickLength + 4, l.x.tick_labels[i], kInk, kTextScale);
    }
    for (size_t i = 0; i < l.y.ticks.size(); ++i) {
        const int y = round_px(l.to_pixel(l.x.lo, l.y.ticks[i]).second);
        c.fill_rect(x0, y, x1, y + 1, kGrid);
        c.fill_rect(x0 - kTickLength, y, x0, y + 1, kInk);
        const int w = Canvas::text_width(l.y.tick_labels[i], kTextScale);
        c.text(x0 - kTickLength - 4 - w, y - line / 2 + 1, l.y.tick_labels[i], kInk, kTextScale);
    }
    c.frame_rect(x0, y0, x1 + 1, y1 + 1, kInk);
}

void draw_marker(Canvas& c, double x, double y, uint32_t rgb) {
    c.disc(x, y, kMarkerRadius, rgb);
}

// Small text up and to the right of a marker; to its left, or under it, where it would cross
// the frame.
void draw_point_label(Canvas& c, const PlotLayout& l, std::pair<double, double> at,
                      const std::string& text) {
    const int w = Canvas::text_width(text, kSmallScale);
    const int px = round_px(at.first), py = round_px(at.second);
    const int x = px + 7 + w > l.right + l.inset - 2 ? px - 7 - w : px + 7;
    const int y = py - 11 < l.top - l.inset + 2 ? py + 5 : py - 11;
    c.text(x, y, text, kPointLabel, kSmallScale);
}

// Polylines first (clipped to the data rectangle), then markers and point labels on top.
void draw_series(Canvas& c, const Plot& plot, const PlotLayout& l) {
    c.set_clip(l.left - l.inset + 1, l.top - l.inset + 1, l.right + l.inset, l.bottom + l.inset);
    for (const PlotSeries& s : plot.series) {
        if (!s.line) continue;
        std::optional<std::pair<double, double>> last;
        for (const auto& p : s.points) {
            if (!drawable(p, plot.log_x)) continue;  // a gap: the line skips the point
            const auto at = l.to_pixel(p.first, p.second);
            if (last) c.line(last->first, last->second, at.first, at.second, s.rgb, kLineThickness);
            last = at;
        }
    }
    c.clear_clip();
    for (const PlotSeries& s : plot.series)
        for (size_t i = 0; i < s.points.size(); ++i) {
            if (!drawable(s.points[i], plot.log_x)) continue;
            const auto at = l.to_pixel(s.points[i].first, s.points[i].second);
            if (s.markers) draw_marker(c, at.first, at.second, s.rgb);
            if (i < s.point_labels.size() && !s.point_labels[i].empty())
                draw_point_label(c, l, at, s.point_labels[i]);
        }
}

// The title over the data, the x label under the tick labels, the y label turned up at the left,
// the legend under it all.
void draw_labels(Canvas& c, const Plot& plot, const PlotLayout& l) {
    const int line = Canvas::text_height(kTextScale);
    const int centre_x = (l.left + l.right) / 2;
    if (!plot.title.empty())
        c.text(centre_x - Canvas::text_width(plot.title, kTextScale) / 2, kPad * 2, plot.title,
               kInk, kTextScale);
    const int x_label_top = l.bottom + l.inset + kTickLength + 4 + line + kPad;
    if (!plot.x_label.empty())
        c.text(centre_x - Canvas::text_width(plot.x_label, kTextScale) / 2, x_label_top,
               plot.x_label, kInk, kTextScale);
    if (!plot.y_label.empty())
        c.text_up(kPad * 2,
                  (l.top + l.bottom) / 2 + Canvas::text_width(plot.y_label, kTextScale) / 2,
                  plot.y_label, kInk, kTextScale);
    const int legend_top = x_label_top + (plot.x_label.empty() ? 0 : line + kPad);
    for (const LegendEntry& e : legend_layout(plot, int(l.width), legend_top)) {
        const double mid = e.y + line / 2.0 - 1;
        if (e.series->line)
            c.line(e.x, mid, e.x + kLegendSample, mid, e.series->rgb, kLineThickness);
        if (e.series->markers) draw_marker(c, e.x + kLegendSample / 2.0, mid, e.series->rgb);
        c.text(e.x + kLegendSample + 6, e.y, e.series->label, kInk, kTextScale);
    }
}

}  // namespace

PlotAxis linear_axis(double lo, double hi, int target) {
    if (!(hi > lo)) {  // one value: a span around it
        const double pad = lo == 0 ? 1 : std::fabs(lo) * 0.1;
        lo -= pad;
        hi += pad;
    }
    const double step = nice_step(hi - lo, target);
    if (!std::isfinite(hi - lo) || !(step > 0) || !std::isfinite(step))
        return two_tick_axis(lo, hi);
    PlotAxis a;
    a.lo = std::floor(lo / step + 1e-9) * step;
    a.hi = std::ceil(hi / step - 1e-9) * step;
    const double intervals = std::round((a.hi - a.lo) / step);
    if (!(a.hi > a.lo) || !(intervals <= 100)) return two_tick_axis(lo, hi);
    const int decimals = std::max(0, -int(std::floor(std::log10(step) + 1e-9)));
    const bool plain = decimals <= 6 && std::max(std::fabs(a.lo), std::fabs(a.hi)) < 1e7;
    for (int i = 0; i <= int(intervals); ++i) {
        double t = a.lo + i * step;
        if (std::fabs(t) < step * 1e-9) t = 0;  // no "-0"
        a.ticks.push_back(t);
        a.tick_labels.push_back(plain ? format_number("%.*f", t, decimals)
                                      : format_number("%.*g", t, 3));
    }
    return a;
}

PlotAxis log_axis(double lo, double hi) {
    int d0 = int(std::floor(std::log10(lo) + 1e-9));
    int d1 = int(std::ceil(std::log10(hi) - 1e-9));
    if (d1 <= d0) --d0, ++d1;  // one value: a decade each side
    PlotAxis a;
    a.log = true;
    a.lo = std::pow(10.0, d0);
    a.hi = std::pow(10.0, d1);
    const int decades = d1 - d0;
    const int every = std::max(1, (decades + 7) / 8);  // at most about 8 labelled decades
    for (int d = d0; d <= d1; d += every)
        for (const double m : {1.0, 2.0, 5.0}) {
            if (m > 1 && decades > 2) continue;
            const double v = m * std::pow(10.0, d);
            if (v > a.hi * (1 + 1e-9)) continue;
            a.ticks.push_back(v);
            a.tick_labels.push_back(format_number("%.*g", v, 6));
        }
    return a;
}

std::pair<double, double> PlotLayout::to_pixel(double px, double py) const {
    const double fx =
        x.log ? (std::log10(px) - std::log10(x.lo)) / (std::log10(x.hi) - std::log10(x.lo))
              : (px - x.lo) / (x.hi - x.lo);
    const double fy = (py - y.lo) / (y.hi - y.lo);
    return {left + fx * (right - left), bottom - fy * (bottom - top)};
}

PlotLayout plot_layout(const Plot& plot, uint32_t width, uint32_t height) {
    PlotLayout l;
    l.width = width;
    l.height = height;
    const std::optional<DataRange> r = data_range(plot);
    if (plot.log_x)
        l.x = r ? log_axis(r->x0, r->x1) : log_axis(1, 10);
    else
        l.x = r ? linear_axis(r->x0, r->x1) : linear_axis(0, 1);
    l.y = r ? linear_axis(r->y0, r->y1) : linear_axis(0, 1);

    const int line = Canvas::text_height(kTextScale);
    const int y_label = plot.y_label.empty() ? 0 : line + kPad;
    l.left = kPad * 2 + y_label + widest(l.y.tick_labels) + kTickLength + 4;
    l.top = plot.title.empty() ? kPad * 2 : line + kPad * 3;
    const int last_tick =
        l.x.tick_labels.empty() ? 0 : Canvas::text_width(l.x.tick_labels.back(), kTextScale) / 2;
    l.right = int(width) - std::max(kPad * 3, last_tick + kPad);
    const int legend = legend_rows(plot, int(width)) * (line + 6);
    const int x_label = plot.x_label.empty() ? 0 : line + kPad;
    l.bottom = int(height) - (kTickLength + 4 + line + kPad + x_label + legend + kPad);
    l.inset = kInset;
    l.left += kInset, l.right -= kInset, l.top += kInset, l.bottom -= kInset;
    if (l.right - l.left < 8 || l.bottom - l.top < 8) {  // a tiny image: the data takes it all
        l.inset = 0;
        l.left = l.top = 0;
        l.right = int(width) - 1;
        l.bottom = int(height) - 1;
    }
    return l;
}

std::vector<uint8_t> render_plot(const Plot& plot, uint32_t width, uint32_t height) {
    const PlotLayout l = plot_layout(plot, width, height);
    Canvas c(width, height, kBackground);
    draw_axes(c, l);
    if (!data_range(plot)) {
        const std::string none = "no points";
        c.text((l.left + l.right - Canvas::text_width(none, kTextScale)) / 2,
               (l.top + l.bottom - Canvas::text_height(kTextScale)) / 2, none, kNoData, kTextScale);
    }
    draw_series(c, plot, l);
    draw_labels(c, plot, l);
    return c.rgba();
}

void write_plot_png(const std::filesystem::path& path, const Plot& plot, uint32_t width,
                    uint32_t height) {
    if (width == 0 || height == 0 || width > kPlotMaxSide || height > kPlotMaxSide)
        throw Error("plot " + escaped(path.string()) + ": size " + std::to_string(width) + "x" +
                    std::to_string(height) + " (1.." + std::to_string(kPlotMaxSide) + " a side)");
    write_file_atomically("plot", path,
                          encode_png_rgba8(path, width, height, render_plot(plot, width, height)));
}

}  // namespace ds::capture
