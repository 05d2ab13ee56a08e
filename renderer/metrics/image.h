#pragma once
// The images the metrics read: 8-bit RGBA as captures store final.png, and one channel of
// doubles (luma, an SSIM map, an error map). Pure CPU, no Vulkan.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace ds::metrics {

// 8-bit RGBA, tightly packed, top row first (a view: the bytes belong to the caller).
struct Rgba8View {
    uint32_t width = 0, height = 0;
    std::span<const uint8_t> rgba;  // width * height * 4 bytes

    uint64_t pixels() const { return uint64_t(width) * height; }
};

// One value per pixel, top row first.
struct LumaImage {
    uint32_t width = 0, height = 0;
    std::vector<double> values;  // width * height

    uint64_t pixels() const { return uint64_t(width) * height; }
    double at(uint32_t x, uint32_t y) const { return values[size_t(y) * width + x]; }
};

// "WxH".
std::string size_text(uint32_t width, uint32_t height);

// Throws ds::Error "WHAT: images of different sizes (WxH and WxH)" unless the sizes agree, and
// "WHAT: WxH image holds N values" when an image's buffer does not match its size.
void require_same_size(const char* what, const Rgba8View& a, const Rgba8View& b);
void require_same_size(const char* what, const LumaImage& a, const LumaImage& b);

}  // namespace ds::metrics
