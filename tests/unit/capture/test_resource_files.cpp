// A capture's files for a Scalar image (issue 23): the PNG decoded from its graph::Display,
// the EXR channel named and typed from it, report.json's entry with a "display" only for
// Scalar images. Made-up images, no device. DS_SCALAR_PNG copies the log heat-mapped PNG
// there, to look at.
#include <gtest/gtest.h>

#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "capture/capture_folder.h"
#include "capture/exr_file.h"
#include "capture/resource_files.h"
#include "renderer/view/heat.h"

namespace ds::capture {
namespace {

namespace fs = std::filesystem;
using graph::Display;
using graph::DisplayRange;

fs::path fresh_dir(const std::string& name) {
    const fs::path dir =
        fs::temp_directory_path() / ("ds-resource-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

// A width x height image of one value per texel: `value(x, y)` in r.
template <typename F>
InspectedImage scalar_image(const std::string& name, const Display& display, uint32_t width,
                            uint32_t height, F value) {
    InspectedImage image;
    image.name = name;
    image.format = VK_FORMAT_R32_SFLOAT;
    image.semantic = graph::Semantic::Scalar;
    image.display = display;
    image.width = width;
    image.height = height;
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x)
            image.texels.insert(image.texels.end(), {value(x, y), 0.0f, 0.0f, 1.0f});
    return image;
}

ResourceSummary summary_of(const InspectedImage& image) {
    return {.name = image.name,
            .format = image.format,
            .width = image.width,
            .height = image.height,
            .semantic = image.semantic};
}

const Display kTriangleArea{.scale = graph::ValueScale::Log,
                            .range = DisplayRange::min_max(),
                            .palette = graph::Palette::Heat,
                            .unit = "px²",
                            .legend = "triangle area",
                            .hover = "triangle {} px²",
                            .exr_channel = "area"};

TEST(ResourceFiles, ScalarExrChannelIsNamedAndTypedByItsDisplay) {
    const InspectedImage area =
        scalar_image("area", kTriangleArea, 2, 1, [](uint32_t x, uint32_t) { return 0.5f + x; });
    const std::vector<ExrChannel> floats = exr_channels(area, "");
    ASSERT_EQ(floats.size(), 1u);
    EXPECT_EQ(floats[0].name, "area");
    EXPECT_FALSE(floats[0].is_uint);
    EXPECT_EQ(floats[0].floats, (std::vector<float>{0.5f, 1.5f}));

    Display counted{.exr_channel = "triangles", .exr_type = graph::ExrType::Uint};
    const InspectedImage triangles =
        scalar_image("tris", counted, 2, 1, [](uint32_t x, uint32_t) { return 2.6f - 3.0f * x; });
    const std::vector<ExrChannel> uints = exr_channels(triangles, "sample1.");
    ASSERT_EQ(uints.size(), 1u);
    EXPECT_EQ(uints[0].name, "sample1.triangles");
    EXPECT_TRUE(uints[0].is_uint);
    EXPECT_EQ(uints[0].uints, (std::vector<uint32_t>{3u, 0u}));  // rounded; negatives 0

    counted.exr_channel.clear();  // no name: "Y"
    EXPECT_EQ(exr_channels(
                  scalar_image("y", counted, 1, 1, [](uint32_t, uint32_t) { return 1.0f; }), "")[0]
                  .name,
              "Y");
}

// 0.01..100 px² over a 256x32 ramp (four decades, left to right) over four rows of zeros.
TEST(ResourceFiles, ScalarImageWritesItsPngExrAndDisplay) {
    const fs::path dir = fresh_dir("scalar");
    const InspectedImage area =
        scalar_image("triangle_area", kTriangleArea, 256, 32, [](uint32_t x, uint32_t y) {
            if (y >= 28) return 0.0f;
            return std::pow(10.0f, -2.0f + 4.0f * x / 255.0f);
        });
    const nlohmann::json entry = write_resource_files(dir, summary_of(area), {&area, 1});
    EXPECT_EQ(entry["semantic"], "Scalar");
    EXPECT_EQ(entry["png"]["unit"], "px²");
    EXPECT_NEAR(entry["png"]["black"].get<double>(), 0.01, 1e-6);
    EXPECT_NEAR(entry["png"]["white"].get<double>(), 100.0, 1e-3);
    EXPECT_EQ(entry["exr"]["channels"],
              nlohmann::json::parse(R"([{"name": "area", "type": "FLOAT"}])"));
    EXPECT_EQ(entry["display"], nlohmann::json::parse(R"({
        "scale": "log", "range": {"rule": "min_max"}, "palette": "heat", "unit": "px²",
        "legend": "triangle area", "hover": "triangle {} px²",
        "exr": {"channel": "area", "type": "FLOAT"}})"));

    const Rgba8Image png = read_png_rgba8(dir / "triangle_area.png");
    ASSERT_EQ(png.width, 256u);
    ASSERT_EQ(png.height, 32u);
    auto at = [&](uint32_t x, uint32_t y) {
        const size_t i = (size_t(y) * png.width + x) * 4;
        return std::array<uint8_t, 3>{png.rgba[i], png.rgba[i + 1], png.rgba[i + 2]};
    };
    EXPECT_EQ(at(0, 0), (std::array<uint8_t, 3>{0, 40, 255}));  // 0.01: the first colour
    EXPECT_EQ(at(255, 0), (std::array<uint8_t, 3>{255, 255, 255}));
    EXPECT_EQ(at(85, 0), view::heat_color(85.0f / 255.0f));   // evenly spaced decades
    EXPECT_EQ(at(0, 31), (std::array<uint8_t, 3>{0, 0, 0}));  // 0: no value
    const ExrImage exr = read_exr(dir / "triangle_area.exr");
    ASSERT_EQ(exr.channels.size(), 1u);
    EXPECT_EQ(exr.channels[0].name, "area");
    EXPECT_FLOAT_EQ(exr.channels[0].floats[255], area.texels[255 * 4]);
    if (const char* copy = std::getenv("DS_SCALAR_PNG"))
        fs::copy_file(dir / "triangle_area.png", copy, fs::copy_options::overwrite_existing);
    fs::remove_all(dir);
}

// The other semantics' entries have no "display" (report.json as before).
TEST(ResourceFiles, OnlyScalarEntriesHaveADisplay) {
    const fs::path dir = fresh_dir("count");
    InspectedImage counts = scalar_image("forward_counts", {}, 2, 2,
                                         [](uint32_t x, uint32_t y) { return float(x + y); });
    counts.semantic = graph::Semantic::Count;
    counts.format = VK_FORMAT_R32_UINT;
    const nlohmann::json entry = write_resource_files(dir, summary_of(counts), {&counts, 1});
    EXPECT_FALSE(entry.contains("display"));
    EXPECT_EQ(entry["png"]["unit"], "count");
    fs::remove_all(dir);
}

}  // namespace
}  // namespace ds::capture
