#pragma once
// Plots as PNG files, for the coming `depthscope tune` commands: series of (x, y) points as
// markers and polylines on axes with nice tick values, axis labels, a legend (the series that
// have a label), point labels beside their markers and a title. Text is stb_easy_font's
// (plot_raster.h); the file goes through the capture PNG encoder and write_file_atomically.
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace ds::capture {

struct PlotSeries {
    std::string label;                              // in the legend; "" leaves the series out of it
    std::vector<std::pair<double, double>> points;  // (x, y); non-finite ones are not drawn
    uint32_t rgb = 0x1f77b4;                        // 0xRRGGBB
    bool line = true;                               // a polyline through the points, in order
    bool markers = true;                            // a filled disc at each point
    std::vector<std::string> point_labels;          // small text beside point i ("" none)
};

struct Plot {
    std::string title, x_label, y_label;
    std::vector<PlotSeries> series;
    bool log_x = false;  // x on a log10 scale (points with x <= 0 are not drawn)
};

// One axis: its range (the data's, widened to whole tick steps) and its ticks.
struct PlotAxis {
    double lo = 0, hi = 1;      // in data units (log_x: the powers of ten at the ends)
    std::vector<double> ticks;  // in data units, lo..hi
    std::vector<std::string> tick_labels;
    bool log = false;
};

// Where things go on the image: the data rectangle [left, right] x [top, bottom] (pixels), where
// the axes' ends lie, inside a frame `inset` pixels around it (a marker at an end stays off
// the frame), and the axes.
struct PlotLayout {
    uint32_t width = 0, height = 0;
    int left = 0, top = 0, right = 0, bottom = 0;
    int inset = 0;
    PlotAxis x, y;

    // A data point's pixel centre (not rounded).
    std::pair<double, double> to_pixel(double x, double y) const;
};

PlotLayout plot_layout(const Plot& plot, uint32_t width, uint32_t height);

// The plot in RGBA8, top row first (what write_plot_png encodes).
std::vector<uint8_t> render_plot(const Plot& plot, uint32_t width, uint32_t height);

// Writes the plot as a PNG through a temporary file renamed onto `path`. Throws ds::Error
// (a size of 0 or over 8192, or a file that cannot be written).
void write_plot_png(const std::filesystem::path& path, const Plot& plot, uint32_t width = 800,
                    uint32_t height = 520);

// The axis of values from lo to hi (lo <= hi, finite): a step of 1, 2 or 5 times a power of
// ten giving about `target` intervals, the ends widened to whole steps; a single value (or no
// values: lo = 0, hi = 1 is the caller's) gets a span around it.
PlotAxis linear_axis(double lo, double hi, int target = 6);
// The same on a log10 scale (0 < lo <= hi): the decades around the values, ticks at the powers
// of ten (and 2 and 5 times them when there are few decades).
PlotAxis log_axis(double lo, double hi);

}  // namespace ds::capture
