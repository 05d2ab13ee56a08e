#include "capture/plot_raster.h"

#include <algorithm>
#include <cmath>

#include <stb/stb_easy_font.h>  // Debian's libstb-dev (header only)

namespace ds::capture {
namespace {

// stb_easy_font reads glyphs of ASCII 32..126 only; anything else would index past its tables.
std::string printable(std::string_view text) {
    std::string out(text);
    for (char& c : out)
        if (c < 32 || c > 126) c = '?';
    return out;
}

// Each filled rectangle of stb_easy_font's glyphs, in font units from the text's top-left:
// put(x0, y0, x1, y1).
template <typename Put>
void easy_font_quads(std::string_view text, Put&& put) {
    std::string chars = printable(text);
    std::vector<char> vertices(chars.size() * 400 + 64);  // ~270 bytes a character (stb)
    const int quads =
        stb_easy_font_print(0, 0, chars.data(), nullptr, vertices.data(), int(vertices.size()));
    for (int q = 0; q < quads; ++q) {
        // Four vertices of 16 bytes (x, y, z floats, RGBA); the first and third are corners.
        float a[2], c[2];
        std::copy_n(&vertices[size_t(q) * 64], sizeof a, reinterpret_cast<char*>(a));
        std::copy_n(&vertices[size_t(q) * 64 + 32], sizeof c, reinterpret_cast<char*>(c));
        put(int(a[0]), int(a[1]), int(c[0]), int(c[1]));
    }
}

}  // namespace

Canvas::Canvas(uint32_t width, uint32_t height, uint32_t background_rgb)
    : width_(width), height_(height), rgba_(size_t(width) * height * 4) {
    clear_clip();
    fill_rect(0, 0, int(width), int(height), background_rgb);
}

uint32_t Canvas::rgb_at(int x, int y) const {
    const uint8_t* p = &rgba_[(size_t(y) * width_ + size_t(x)) * 4];
    return uint32_t(p[0]) << 16 | uint32_t(p[1]) << 8 | p[2];
}

void Canvas::set_clip(int x0, int y0, int x1, int y1) {
    clip_x0_ = std::max(x0, 0);
    clip_y0_ = std::max(y0, 0);
    clip_x1_ = std::min(x1, int(width_));
    clip_y1_ = std::min(y1, int(height_));
}

void Canvas::clear_clip() {
    set_clip(0, 0, int(width_), int(height_));
}

void Canvas::pixel(int x, int y, uint32_t rgb) {
    if (x < clip_x0_ || y < clip_y0_ || x >= clip_x1_ || y >= clip_y1_) return;
    uint8_t* p = &rgba_[(size_t(y) * width_ + size_t(x)) * 4];
    p[0] = uint8_t(rgb >> 16);
    p[1] = uint8_t(rgb >> 8);
    p[2] = uint8_t(rgb);
    p[3] = 255;
}

void Canvas::fill_rect(int x0, int y0, int x1, int y1, uint32_t rgb) {
    for (int y = std::max(y0, clip_y0_); y < std::min(y1, clip_y1_); ++y)
        for (int x = std::max(x0, clip_x0_); x < std::min(x1, clip_x1_); ++x) pixel(x, y, rgb);
}

void Canvas::frame_rect(int x0, int y0, int x1, int y1, uint32_t rgb) {
    fill_rect(x0, y0, x1, y0 + 1, rgb);
    fill_rect(x0, y1 - 1, x1, y1, rgb);
    fill_rect(x0, y0, x0 + 1, y1, rgb);
    fill_rect(x1 - 1, y0, x1, y1, rgb);
}

void Canvas::line(double x0, double y0, double x1, double y1, uint32_t rgb, int thickness) {
    if (!std::isfinite(x0) || !std::isfinite(y0) || !std::isfinite(x1) || !std::isfinite(y1))
        return;
    // Far-off ends (a point beyond the axes) would take forever to step: the canvas bounds them.
    const double limit = 4.0 * std::max(width_, height_) + 16;
    if (std::max({std::fabs(x0), std::fabs(y0), std::fabs(x1), std::fabs(y1)}) > limit) return;
    const int steps = int(std::ceil(std::max(std::fabs(x1 - x0), std::fabs(y1 - y0)))) + 1;
    const int half = (thickness - 1) / 2;
    for (int i = 0; i <= steps; ++i) {
        const double t = double(i) / steps;
        const int x = int(std::lround(x0 + (x1 - x0) * t)) - half;
        const int y = int(std::lround(y0 + (y1 - y0) * t)) - half;
        fill_rect(x, y, x + thickness, y + thickness, rgb);
    }
}

void Canvas::disc(double cx, double cy, double radius, uint32_t rgb) {
    const int x0 = int(std::floor(cx - radius)), x1 = int(std::ceil(cx + radius));
    const int y0 = int(std::floor(cy - radius)), y1 = int(std::ceil(cy + radius));
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x)
            if (std::hypot(x - cx, y - cy) <= radius) pixel(x, y, rgb);
}

void Canvas::text(int x, int y, std::string_view text, uint32_t rgb, int scale) {
    easy_font_quads(text, [&](int x0, int y0, int x1, int y1) {
        fill_rect(x + x0 * scale, y + y0 * scale, x + x1 * scale, y + y1 * scale, rgb);
    });
}

void Canvas::text_up(int x, int y, std::string_view text, uint32_t rgb, int scale) {
    // Font (u, v) lands on (x + v, y - u): u runs up the canvas, v to the right.
    easy_font_quads(text, [&](int u0, int v0, int u1, int v1) {
        fill_rect(x + v0 * scale, y - u1 * scale, x + v1 * scale, y - u0 * scale, rgb);
    });
}

int Canvas::text_width(std::string_view text, int scale) {
    std::string chars = printable(text);
    return stb_easy_font_width(chars.data()) * scale;
}

int Canvas::text_height(int scale) {
    return 9 * scale;
}

}  // namespace ds::capture
