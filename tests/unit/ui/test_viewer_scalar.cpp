// The viewer's composer on a made-up frame with Scalar images (issue 23): the decode, the
// colour bar legend and the hover text come from each image's graph::Display, never from its
// name (a Scalar image named like a count image is no count). No device used.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ui/inspector.h"
#include "ui/view_composer.h"

namespace ds::test {
namespace {

using graph::Display;
using graph::DisplayRange;

InspectedImage scalar(const std::string& name, const Display& display,
                      const std::vector<float>& values) {
    InspectedImage image;
    image.name = name;
    image.format = VK_FORMAT_R32_SFLOAT;
    image.semantic = graph::Semantic::Scalar;
    image.display = display;
    image.width = uint32_t(values.size());
    image.height = 1;
    for (float v : values) image.texels.insert(image.texels.end(), {v, 0.0f, 0.0f, 1.0f});
    return image;
}

const Display kTriangleArea{.scale = graph::ValueScale::Log,
                            .range = DisplayRange::min_max(),
                            .palette = graph::Palette::Heat,
                            .unit = "px²",
                            .legend = "triangle area",
                            .hover = "triangle {} px²"};

TEST(ViewerScalar, LegendAndHoverComeFromTheDisplay) {
    FrameResult frame;
    frame.inspected = scalar("triangle_area", kTriangleArea, {0.01f, 0.18f, 10.0f, 100.0f});
    ui::ViewerState viewer;
    viewer.resource = "triangle_area";
    ui::ViewComposer composer;
    view::DecodedView out;
    ASSERT_EQ(composer.decode_shown(frame, viewer, out), &*frame.inspected);
    EXPECT_EQ(out.unit, "px²");
    EXPECT_EQ(out.rgba8, view::decode(*frame.inspected, view::ViewParams{}).rgba8);
    ASSERT_EQ(composer.legends().size(), 1u);
    const ui::ViewLegend& legend = composer.legends()[0];
    EXPECT_EQ(legend.label, "triangle area");
    EXPECT_FLOAT_EQ(legend.black, 0.01f);
    EXPECT_FLOAT_EQ(legend.white, 100.0f);
    ASSERT_TRUE(legend.display);
    EXPECT_EQ(legend.display->unit, "px²");
    EXPECT_EQ(composer.text_at(frame, "triangle_area", 1, 0), "triangle 0.18 px²");
}

// Named like a pass's count image, grey on a fixed range: no heat scale shared with the pass,
// no legend; an overlay of the heat-mapped image adds its colour bar.
TEST(ViewerScalar, NameIsNotKind) {
    FrameResult frame;
    const Display grey{.range = DisplayRange::fixed(0.0f, 10.0f), .hover = "{} ms"};
    frame.inspected = scalar("forward_counts", grey, {5.0f, 20.0f});
    frame.overlays.push_back(scalar("triangle_area", kTriangleArea, {1.0f, 0.0f}));
    ui::ViewerState viewer;
    viewer.resource = "forward_counts";
    viewer.overlays.push_back({"triangle_area", 1.0f, true});
    ui::ViewComposer composer;
    view::DecodedView out;
    ASSERT_TRUE(composer.decode_shown(frame, viewer, out));
    EXPECT_EQ(out.black, 0.0f);
    EXPECT_EQ(out.white, 10.0f);
    EXPECT_EQ(out.rgba8[0], 128);  // 5 of 0..10, grey
    EXPECT_TRUE(composer.legends().empty());
    EXPECT_EQ(composer.text_at(frame, "forward_counts", 1, 0), "20 ms");
    composer.stack_overlays(frame, viewer, out);
    ASSERT_EQ(composer.legends().size(), 1u);
    EXPECT_EQ(composer.legends()[0].label, "triangle area");
}

}  // namespace
}  // namespace ds::test
