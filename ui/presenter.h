#pragma once
// The inspector's presentation layer, one of the two ui/ files that call Vulkan (window.cpp,
// the surface and swapchain, is the other). One UI frame is
// a small render graph of its own on the renderer's device (renderer/graph, so its barriers
// and layout transitions are planned like the frame's):
//   ui_upload  the viewer's decoded pixels, staging buffer -> display image
//   ui_viewer  clear the target, blit the display image into the viewer's rectangle (zoom,
//              pan, nearest when magnified)
//   ui_imgui   Dear ImGui's draw data (the 1.86 Vulkan backend, which needs a VkRenderPass)
// onto a target: a swapchain image (ui/window.h) or an offscreen image read back to pixels
// (capture --ui, bench --ui, tests).
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/graph/graph.h"
#include "renderer/readback/host_readback.h"
#include "renderer/vk/buffer.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/frame.h"
#include "renderer/vk/handle.h"
#include "renderer/vk/image.h"
#include "ui/viewer_blit.h"

struct ImDrawData;

namespace ds::vk {
class Context;
}

namespace ds::ui {

// What the UI graph drew into, and its GPU time.
struct UiFrameStats {
    double gpu_ms = 0;  // the three passes, from their timestamps
};

class Presenter {
  public:
    static constexpr VkFormat kOffscreenFormat = VK_FORMAT_B8G8R8A8_UNORM;

    // Needs a current ImGui context; initialises the ImGui Vulkan backend for `target_format`
    // and uploads the font atlas.
    Presenter(vk::Context& context, VkFormat target_format);
    ~Presenter();  // waits for the device; shuts the backend down
    Presenter(const Presenter&) = delete;
    Presenter& operator=(const Presenter&) = delete;

    VkFormat target_format() const { return format_; }

    // A target image the caller owns (a swapchain image): its layout before (UNDEFINED) and
    // after (PRESENT_SRC) are the graph's import states.
    struct Target {
        VkImage image = VK_NULL_HANDLE;
        VkImageView view = VK_NULL_HANDLE;
        VkExtent2D extent{0, 0};
    };
    // Records one UI frame into a frame of the presenter's ring and submits it, waiting on
    // `acquired` and signalling `rendered` (either may be null). Returns after the submit;
    // the frame's fence is waited at the next frame (or wait_idle()).
    UiFrameStats present(const Target& target, const ViewerBlit& viewer, ImDrawData* draw,
                         VkSemaphore acquired, VkSemaphore rendered);
    // The same onto an offscreen image of `extent`, read back: RGBA8, row 0 = top. Blocks.
    std::vector<uint8_t> render_offscreen(VkExtent2D extent, const ViewerBlit& viewer,
                                          ImDrawData* draw, UiFrameStats* stats = nullptr);

    // Swapchain images are about to be destroyed: waits until no frame uses their views.
    void forget_targets();
    void wait_idle();

  private:
    // The UI frame's graph passes (ui_upload only when the viewer has an image to blit).
    graph::ImageHandle add_upload(const ViewerBlit& viewer, vk::DestroyList& retired);
    void add_viewer(graph::ImageHandle ui, graph::ImageHandle display, const BlitRegion& region,
                    bool nearest);
    void add_imgui(graph::ImageHandle ui, ImDrawData* draw);
    void add_readback(graph::ImageHandle ui);
    // `read_back`: a ui_readback pass copies the target to a host buffer (render_offscreen).
    void record(VkCommandBuffer cmd, const Target& target, const graph::ExternalState& final,
                const ViewerBlit& viewer, ImDrawData* draw, vk::DestroyList& retired,
                bool read_back = false);
    void ensure_display(uint32_t width, uint32_t height, vk::DestroyList& retired);
    UiFrameStats collect(uint64_t id) const;

    vk::Context& context_;
    VkFormat format_;
    vk::DescriptorPool imgui_pool_;
    vk::RenderPass render_pass_;
    std::unique_ptr<vk::FrameRing> frames_;
    std::unique_ptr<graph::RenderGraph> graph_;
    vk::Image display_;  // the viewer's pixels, RGBA8
    vk::Buffer staging_;
    uint64_t uploaded_version_ = 0;  // the ViewerBlit::version display_ holds
    vk::Image offscreen_;
    std::unique_ptr<HostReadback> readback_;  // the offscreen target's pixels
    graph::ImageHandle target_;               // the last frame's target in graph_
    uint64_t last_graph_frame_ = 0;
    bool backend_ = false;
};

}  // namespace ds::ui
