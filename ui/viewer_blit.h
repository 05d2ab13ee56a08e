#pragma once
// What the viewer shows and where, as plain numbers: the inspector's model fills a ViewerBlit,
// ui::Presenter draws it, and the viewer panel maps the cursor through the same integer
// rectangles so the readout names the texel drawn there. No Vulkan here (the panels and the
// inspector's model include it).
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace ds::ui {

// Where the viewer's image goes, in target pixels, and which part of the image: the
// compositor scales src to dst (both may extend past the image or the viewport; they are
// clipped together).
struct ViewerBlit {
    const std::vector<uint8_t>* rgba8 = nullptr;  // width * height * 4; null: no image
    uint32_t width = 0, height = 0;
    float dst_x = 0, dst_y = 0, dst_w = 0, dst_h = 0;  // the viewport on the target
    float src_x = 0, src_y = 0, src_w = 0, src_h = 0;  // the image region shown in it
    bool nearest = true;
    // Changes whenever the pixels do; the presenter uploads them again only then (0: always).
    uint64_t version = 0;
};

// The target's size in pixels (a swapchain image, the offscreen image, ImGui's framebuffer).
struct TargetSize {
    uint32_t width = 0, height = 0;
};

// The integer rectangles the viewer's blit copies (source texels -> target pixels), the image
// and the viewport clipped together; false when nothing of the image is visible.
struct BlitRegion {
    int32_t sx0, sy0, sx1, sy1, dx0, dy0, dx1, dy1;
};
bool clip_blit(const ViewerBlit& viewer, TargetSize target, BlitRegion& out);
// The texel the blit shows at target pixel (x, y); none outside the image.
std::optional<std::array<uint32_t, 2>> texel_at(const ViewerBlit& viewer, TargetSize target,
                                                float x, float y);

}  // namespace ds::ui
