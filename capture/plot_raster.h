#pragma once
// The plot writer's (plot.h) rasteriser: an RGBA8 canvas with filled rectangles, thick lines,
// discs and stb_easy_font's text (ASCII; its segments filled as rectangles, `scale` pixels per
// font unit). Colours are 0xRRGGBB, always opaque. Everything is clipped to the canvas, and to
// the clip rectangle while one is set.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ds::capture {

class Canvas {
  public:
    Canvas(uint32_t width, uint32_t height, uint32_t background_rgb);

    int width() const { return int(width_); }
    int height() const { return int(height_); }
    // Top row first, 4 bytes a pixel.
    const std::vector<uint8_t>& rgba() const { return rgba_; }
    uint32_t rgb_at(int x, int y) const;

    // Drawing is limited to [x0, x1) x [y0, y1) until clear_clip().
    void set_clip(int x0, int y0, int x1, int y1);
    void clear_clip();

    void pixel(int x, int y, uint32_t rgb);
    void fill_rect(int x0, int y0, int x1, int y1, uint32_t rgb);   // [x0, x1) x [y0, y1)
    void frame_rect(int x0, int y0, int x1, int y1, uint32_t rgb);  // its 1-pixel outline
    // From (x0, y0) to (x1, y1), `thickness` pixels wide.
    void line(double x0, double y0, double x1, double y1, uint32_t rgb, int thickness);
    void disc(double cx, double cy, double radius, uint32_t rgb);

    // `text` with its top-left corner at (x, y); characters outside printable ASCII show as '?'.
    void text(int x, int y, std::string_view text, uint32_t rgb, int scale);
    // Turned a quarter counter-clockwise (read bottom to top), its bottom-left corner at (x, y)
    // after the turn: it extends up from y and right from x by text_height.
    void text_up(int x, int y, std::string_view text, uint32_t rgb, int scale);
    static int text_width(std::string_view text, int scale);
    static int text_height(int scale);  // of a line, descenders included

  private:
    uint32_t width_, height_;
    std::vector<uint8_t> rgba_;
    int clip_x0_ = 0, clip_y0_ = 0, clip_x1_ = 0, clip_y1_ = 0;
};

}  // namespace ds::capture
