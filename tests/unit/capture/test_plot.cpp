// The plot writer (capture/plot.h): the PNG's size, a marker's colour at its data point's pixel,
// nice ticks, and plots with nothing, one point or equal values (no crash, no division by zero).
// DS_TEST_SHOTS=DIR also writes a sample plot there to look at.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <string>

#include "capture/capture_folder.h"
#include "capture/plot.h"
#include "renderer/common/error.h"

namespace fs = std::filesystem;

namespace ds::capture {
namespace {

fs::path plot_dir() {
    const fs::path dir = fs::temp_directory_path() / ("ds-plot-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

uint32_t rgb_at(const Rgba8Image& image, double x, double y) {
    const size_t p = (size_t(std::lround(y)) * image.width + size_t(std::lround(x))) * 4;
    return uint32_t(image.rgba[p]) << 16 | uint32_t(image.rgba[p + 1]) << 8 | image.rgba[p + 2];
}

// What a `tune` sweep will plot: quality against cost, one labelled point per setting.
Plot sample_plot() {
    Plot plot;
    plot.title = "SSIM against GPU time (atrium, 1280x720)";
    plot.x_label = "forward gpu_ms";
    plot.y_label = "SSIM of final.png";
    plot.series.push_back({"msaa 1",
                           {{1.2, 0.962}, {1.9, 0.975}, {3.1, 0.981}},
                           0x1f77b4,
                           true,
                           true,
                           {"alpha 0.3", "alpha 0.5", "alpha 0.7"}});
    plot.series.push_back(
        {"msaa 4", {{2.4, 0.985}, {3.8, 0.991}, {6.5, 0.994}}, 0xd62728, true, true, {}});
    plot.series.push_back({"reference", {{6.5, 1.0}}, 0x2ca02c, false, true, {"ground truth"}});
    return plot;
}

TEST(Plot, PngOfTheAskedSize) {
    const fs::path dir = plot_dir();
    write_plot_png(dir / "default.png", sample_plot());
    const Rgba8Image image = read_png_rgba8(dir / "default.png");
    EXPECT_EQ(image.width, 800u);
    EXPECT_EQ(image.height, 520u);
    write_plot_png(dir / "small.png", sample_plot(), 333, 211);
    const Rgba8Image small = read_png_rgba8(dir / "small.png");
    EXPECT_EQ(small.width, 333u);
    EXPECT_EQ(small.height, 211u);
    write_plot_png(dir / "small.png", Plot{}, 64, 48);  // replaces a regular file
    EXPECT_EQ(read_png_rgba8(dir / "small.png").width, 64u);
    if (const char* shots = std::getenv("DS_TEST_SHOTS")) {  // to look at
        write_plot_png(fs::path(shots) / "plot.png", sample_plot());
        Plot log = sample_plot();
        log.log_x = true;
        log.title = "the same, log x";
        write_plot_png(fs::path(shots) / "plot_log.png", log);
        write_plot_png(fs::path(shots) / "plot_empty.png", Plot{"nothing", "x", "y", {}, false});
    }
    EXPECT_THROW(write_plot_png(dir / "zero.png", sample_plot(), 0, 10), Error);
    EXPECT_THROW(write_plot_png(dir, sample_plot()), Error);  // a folder is not replaced
    fs::remove_all(dir);
}

TEST(Plot, MarkerHasTheSeriesColourAtItsDataPoint) {
    for (const bool log_x : {false, true}) {
        Plot plot;
        plot.log_x = log_x;
        plot.series.push_back({"a", {{1, 2}, {30, 5}, {700, 4}}, 0xd62728, false, true, {}});
        const PlotLayout layout = plot_layout(plot, 640, 400);
        const fs::path dir = plot_dir();
        write_plot_png(dir / "p.png", plot, 640, 400);
        const Rgba8Image image = read_png_rgba8(dir / "p.png");
        fs::remove_all(dir);
        for (const auto& [x, y] : plot.series[0].points) {
            const auto [px, py] = layout.to_pixel(x, y);
            EXPECT_GE(px, layout.left);
            EXPECT_LE(px, layout.right);
            EXPECT_EQ(rgb_at(image, px, py), 0xd62728u) << x << " log " << log_x;
        }
        // The corners of the data rectangle are the axes' ends.
        EXPECT_DOUBLE_EQ(layout.to_pixel(layout.x.lo, layout.y.lo).first, layout.left);
        EXPECT_DOUBLE_EQ(layout.to_pixel(layout.x.hi, layout.y.hi).second, layout.top);
        // Background away from everything.
        EXPECT_EQ(rgb_at(image, 2, 2), 0xffffffu);
    }
}

TEST(Plot, NiceTicks) {
    const PlotAxis a = linear_axis(0, 97);
    EXPECT_EQ(a.ticks, (std::vector<double>{0, 20, 40, 60, 80, 100}));
    EXPECT_EQ(a.tick_labels.front(), "0");
    EXPECT_EQ(a.tick_labels.back(), "100");
    const PlotAxis b = linear_axis(0.962, 1.0);
    EXPECT_NEAR(b.lo, 0.96, 1e-12);
    EXPECT_NEAR(b.hi, 1.0, 1e-12);
    EXPECT_EQ(b.tick_labels.front(), "0.960");
    EXPECT_EQ(b.tick_labels.back(), "1.000");
    const PlotAxis c = linear_axis(-3, 3);
    EXPECT_EQ(c.tick_labels, (std::vector<std::string>{"-3", "-2", "-1", "0", "1", "2", "3"}));
    const PlotAxis l = log_axis(3, 4000);
    EXPECT_EQ(l.ticks, (std::vector<double>{1, 10, 100, 1000, 10000}));
    EXPECT_EQ(log_axis(20, 70).tick_labels, (std::vector<std::string>{"10", "20", "50", "100"}));
}

// Nothing to plot, one point, equal values, points that cannot be drawn, tiny images: an image
// all the same, and axes of a positive span.
TEST(Plot, DegenerateInputs) {
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    constexpr double kInf = std::numeric_limits<double>::infinity();
    const std::vector<Plot> plots = {
        Plot{},
        Plot{"t", "x", "y", {PlotSeries{"empty", {}, 0xff0000, true, true, {}}}, false},
        Plot{"one", "", "", {PlotSeries{"p", {{5, 5}}, 0xff0000, true, true, {"5,5"}}}, false},
        Plot{"zero", "", "", {PlotSeries{"p", {{0, 0}, {0, 0}}, 0xff0000, true, true, {}}}, true},
        Plot{"equal",
             "",
             "",
             {PlotSeries{"", {{1, 7}, {2, 7}, {3, 7}}, 0xff, true, true, {}}},
             false},
        Plot{"same x", "", "", {PlotSeries{"", {{4, 1}, {4, 9}}, 0xff, true, true, {}}}, true},
        Plot{"bad",
             "",
             "",
             {PlotSeries{"\x01\xff",
                         {{kNaN, 1}, {1, kInf}, {-1, 2}, {1e300, -1e300}},
                         0xff,
                         true,
                         true,
                         {"\n"}}},
             true},
        Plot{"huge",
             "",
             "",
             {PlotSeries{"", {{-1e308, -1e308}, {1e308, 1e308}}, 0xff, true, true, {}}},
             false},
        Plot{"tiny",
             "",
             "",
             {PlotSeries{"", {{0, 1e-310}, {1, 2e-310}}, 0xff, true, true, {}}},
             false},
    };
    for (const Plot& plot : plots)
        for (const auto& [w, h] : {std::pair{800u, 520u}, std::pair{40u, 30u}, std::pair{1u, 1u}}) {
            const PlotLayout l = plot_layout(plot, w, h);
            EXPECT_TRUE(std::isfinite(l.x.lo) && std::isfinite(l.x.hi) && l.x.hi > l.x.lo)
                << plot.title;
            EXPECT_TRUE(std::isfinite(l.y.lo) && std::isfinite(l.y.hi) && l.y.hi > l.y.lo)
                << plot.title;
            EXPECT_EQ(render_plot(plot, w, h).size(), size_t(w) * h * 4) << plot.title;
        }
}

}  // namespace
}  // namespace ds::capture
