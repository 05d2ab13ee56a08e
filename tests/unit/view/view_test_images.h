#pragma once
// Hand-made images for the view library's tests (decode_tests, readout_tests): the renderer's
// depth conventions, images from texel lists, and the decoded pixel at a position.
#include <array>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "renderer/view/decode.h"

namespace ds::view::test {

using Rgb = std::array<uint8_t, 3>;

inline constexpr float kNear = 0.1f, kFar = 100.0f;

// The renderer's projections (finite far): stored depth of a view distance d.
inline float reverse_z_stored(float d, float n = kNear, float f = kFar) {
    return n * (f - d) / ((f - n) * d);
}
inline float forward_z_stored(float d, float n = kNear, float f = kFar) {
    return f * (d - n) / ((f - n) * d);
}

// A width x height image whose texel i is texels[i] (rgba).
inline InspectedImage make_image(graph::Semantic semantic, VkFormat format, uint32_t width,
                                 uint32_t height, const std::vector<std::array<float, 4>>& texels) {
    InspectedImage image;
    image.name = "test";
    image.format = format;
    image.semantic = semantic;
    image.width = width;
    image.height = height;
    image.znear = kNear;
    image.zfar = kFar;
    image.reverse_z = semantic != graph::Semantic::ForwardZDepth;
    for (const auto& t : texels) image.texels.insert(image.texels.end(), t.begin(), t.end());
    return image;
}

// A 1-row image of scalars in r (g = b = 0, a = 1, as a shader samples an R format).
inline InspectedImage scalar_row(graph::Semantic semantic, VkFormat format,
                                 const std::vector<float>& values) {
    std::vector<std::array<float, 4>> texels;
    for (float v : values) texels.push_back({v, 0.0f, 0.0f, 1.0f});
    return make_image(semantic, format, uint32_t(values.size()), 1, texels);
}

inline Rgb pixel(const DecodedView& view, uint32_t x, uint32_t y = 0) {
    const size_t i = (size_t(y) * view.width + x) * 4;
    EXPECT_LT(i + 3, view.rgba8.size());
    EXPECT_EQ(view.rgba8[i + 3], 255) << "alpha at " << x << "," << y;
    return {view.rgba8[i], view.rgba8[i + 1], view.rgba8[i + 2]};
}

inline ViewParams manual(float black, float white) {
    ViewParams p;
    p.auto_fit = false;
    p.black = black;
    p.white = white;
    return p;
}

}  // namespace ds::view::test
